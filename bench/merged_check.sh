#!/usr/bin/env bash
# The merged tree of 2026-11-23 (speed + gi-accuracy + dsm) on the GPU machine: issue 14's full frames
# (hardware and compute raster), cornell's LPV frame, and issue 15's hair frames with camera translucency.
# Usage: bench/merged_check.sh PENUMBRA ASSETS_DIR OUT_DIR
set -euo pipefail
bin=$1 assets=$2 out=$3
mkdir -p "$out"
full="--shadow pcf --cascades 4 --shadow-res 2048 --gi lpv --lpv-res 32 --lpv-iterations 8 --width 1920 --height 1080"
frames="--frames 60 --warmup 10"
sponza="$assets/sponza/glTF/Sponza.gltf --camera -9,1.7,0.3,6,4.5,0,0,1,0,70 --light directional,0.1,-1,0.2,20"
vc="$assets/VC/glTF/VC.gltf --camera 14,9,16,0,1.5,0,0,1,0,50"
run() {  # NAME ARGS...
  local name=$1; shift
  "$bin" bench "$@" $frames --json "$out/$name.json" > "$out/$name.txt" 2>&1 || echo "FAILED $name"
  grep -E "frame \(GPU|warm frame" "$out/$name.txt" | sed "s/^/$name: /"
}
run sponza_1920x1080_full-frame-merged $sponza $full
run sponza_1920x1080_full-frame-merged-compute $sponza $full --raster compute
run vc_1920x1080_full-frame-merged $vc $full
run vc_1920x1080_full-frame-merged-compute $vc $full --raster compute
run cornell_1920x1080_gi-lpv-merged cornell --width 1920 --height 1080 --gi lpv
for n in 25000 100000; do
  run hair-${n}_1920x1080_dsm-merged hair --strands $n --shadow dsm --dsm-res 2048 --width 1920 --height 1080
done
