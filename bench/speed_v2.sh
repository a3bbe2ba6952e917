#!/usr/bin/env bash
# Issue 14 on the GPU machine: the full frames and Cornell's LPV frame with one light-view raster,
# the visibility-buffer camera path (default) against the classic G-buffer, and the compute
# rasterizer; cold frames (every pass runs) with warm ones beside them in each JSON.
# Usage: bench/speed_v2.sh PENUMBRA ASSETS_DIR OUT_DIR
set -euo pipefail
bin=$1 assets=$2 out=$3
mkdir -p "$out"
techniques="--shadow pcf --cascades 4 --shadow-res 2048 --gi lpv --lpv-res 32 --lpv-iterations 8"
full="$techniques --width 1920 --height 1080"
frames="--frames 60 --warmup 10"
sponza="$assets/sponza/glTF/Sponza.gltf --camera -9,1.7,0.3,6,4.5,0,0,1,0,70 --light directional,0.1,-1,0.2,20"
vc="$assets/VC/glTF/VC.gltf --camera 14,9,16,0,1.5,0,0,1,0,50"
run() {  # NAME ARGS...
  local name=$1; shift
  "$bin" bench "$@" $frames --json "$out/$name.json" > "$out/$name.txt" 2>&1 || echo "FAILED $name"
  grep -E "frame \(GPU|warm frame" "$out/$name.txt" | sed "s/^/$name: /"
}
for scene in sponza vc; do
  args=${!scene}
  run ${scene}_1920x1080_full-frame-v2 $args $full
  run ${scene}_1920x1080_full-frame-v2-gbuffer $args $full --camera-path gbuffer
  run ${scene}_1920x1080_full-frame-v2-compute $args $full --raster compute
done
run cornell_1920x1080_gi-lpv-v2 cornell --width 1920 --height 1080 --gi lpv
run cornell_1920x1080_gi-lpv-v2-gbuffer cornell --width 1920 --height 1080 --gi lpv --camera-path gbuffer
run cornell_1920x1080_gi-none-v2 cornell --width 1920 --height 1080 --gi none
# Images: the visibility path against the classic G-buffer on the textured scenes (final AOV, EXR).
for scene in sponza vc; do
  args=${!scene}
  for path in visibility gbuffer; do
    "$bin" render $args $techniques --width 960 --height 540 --camera-path $path -o "$out/${scene}_$path.exr" > /dev/null 2>&1
  done
  "$bin" compare "$out/${scene}_visibility.exr" "$out/${scene}_gbuffer.exr" --json > "$out/${scene}_visibility-vs-gbuffer.json" 2>&1 || true
  rm -f "$out/${scene}_visibility.exr" "$out/${scene}_gbuffer.exr"
done
