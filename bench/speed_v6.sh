#!/usr/bin/env bash
# 2026-11-26, end of session: issue 14's target commands under the names it asks for (cold frames;
# --raster left at its default, auto: the compute rasterizer on the H100), each also with --raster
# hardware (where the raster hardware wins), LPV's defaults, cornell's GI frames, and issue 15's
# hair frames (DSM and deep opacity maps, 25k and 100k strands, camera translucency on).
# Usage (device): bench/speed_v6.sh PENUMBRA ASSETS_DIR OUT_DIR
set -euo pipefail
bin=$1 assets=$2 out=$3
. "$(dirname "$0")/lib.sh"
newLpv="--shadow pcf --cascades 4 --shadow-res 2048 --gi lpv --width 1920 --height 1080"
for scene in sponza vc; do
  run ${scene}_1920x1080_full-frame ${!scene} $full
  run ${scene}_1920x1080_full-frame-hardware ${!scene} $full --raster hardware
  run ${scene}_1920x1080_full-frame-new-lpv ${!scene} $newLpv
  run ${scene}_1920x1080_gi-rsm ${!scene} --width 1920 --height 1080 --gi rsm
done
run cornell_1920x1080_gi-lpv cornell --width 1920 --height 1080 --gi lpv
run cornell_1920x1080_gi-lpv-hardware cornell --width 1920 --height 1080 --gi lpv --raster hardware
run cornell_1920x1080_gi-rsm cornell --width 1920 --height 1080 --gi rsm
for n in 25000 100000; do
  for t in dsm dom; do
    run hair_1920x1080_${t}-$n hair --dsm-res 2048 --width 1920 --height 1080 --shadow $t --strands $n
  done
done
summarize
