#!/usr/bin/env bash
# Issue 14 after the compute rasterizer learned visibility IDs (2026-11-24): the full frames and
# Cornell's LPV frame under --raster auto (compute on the H100), hardware and compute; Sponza's RSM
# frame, whose cascade carries IDs. Cold frames, warm ones beside them in each JSON.
# Usage: bench/speed_v3.sh PENUMBRA ASSETS_DIR OUT_DIR
set -euo pipefail
bin=$1 assets=$2 out=$3
. "$(dirname "$0")/lib.sh"
for scene in sponza vc; do
  args=${!scene}
  for raster in auto hardware compute; do
    run ${scene}_1920x1080_full-frame-v3-$raster $args $full --raster $raster
  done
  run ${scene}_1920x1080_gi-rsm-v3-compute $args ${full/--gi lpv/--gi rsm} --raster compute
  run ${scene}_1920x1080_gi-rsm-v3-hardware $args ${full/--gi lpv/--gi rsm} --raster hardware
done
for raster in auto hardware; do
  run cornell_1920x1080_gi-lpv-v3-$raster cornell --width 1920 --height 1080 --gi lpv --raster $raster
done
for f in "$out"/sponza_1920x1080_full-frame-v3-*.txt "$out"/sponza_1920x1080_gi-rsm-v3-*.txt; do
  echo "== $f"; grep -E "shadow\.|rsm\.|gbuffer|visibility|frame" "$f" | head -30
done
