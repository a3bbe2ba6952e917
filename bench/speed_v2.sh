#!/usr/bin/env bash
# Issue 14 on the GPU machine: the full frames and Cornell's LPV frame with one light-view raster,
# the visibility-buffer camera path (default) against the classic G-buffer, and the compute
# rasterizer; cold frames (every pass runs) with warm ones beside them in each JSON.
# Usage: bench/speed_v2.sh PENUMBRA ASSETS_DIR OUT_DIR
set -euo pipefail
bin=$1 assets=$2 out=$3
. "$(dirname "$0")/lib.sh"
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
