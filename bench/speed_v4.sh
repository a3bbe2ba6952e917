#!/usr/bin/env bash
# 2026-11-24, end of session: the compute rasterizer draws the camera's visibility buffer too, and LPV
# has new defaults (16^3 x 8, 3 cascades everywhere). Issue 14's full frames (its fixed LPV options,
# then LPV's new defaults), Cornell's LPV frame, and issue 13's GI pass costs, each under --raster
# hardware (the default) and auto (the compute rasterizer on the H100). Cold frames.
# Usage: bench/speed_v4.sh PENUMBRA ASSETS_DIR OUT_DIR
set -euo pipefail
bin=$1 assets=$2 out=$3
. "$(dirname "$0")/lib.sh"
newLpv="--shadow pcf --cascades 4 --shadow-res 2048 --gi lpv --width 1920 --height 1080"
for raster in hardware auto; do
  for scene in sponza vc; do
    args=${!scene}
    run ${scene}_1920x1080_full-frame-v4-$raster $args $full --raster $raster
    run ${scene}_1920x1080_full-frame-new-lpv-v4-$raster $args $newLpv --raster $raster
  done
  run cornell_1920x1080_gi-lpv-v4-$raster cornell --width 1920 --height 1080 --gi lpv --raster $raster
  run cornell_1920x1080_gi-rsm-v4-$raster cornell --width 1920 --height 1080 --gi rsm --raster $raster
  run vc_1920x1080_gi-rsm-v4-$raster $vc --width 1920 --height 1080 --gi rsm --raster $raster
done
for f in "$out"/*-auto.txt; do
  echo "== $f"; grep -E "visibility|shadow\.raster|lpv\.|rsm\.|frame \(GPU" "$f" | grep -v "propagate\[[1-6]\]" | head -40
done
