#!/usr/bin/env bash
# The merged tree of 2026-11-23 (speed + gi-accuracy + dsm) on the GPU machine: issue 14's full frames
# (hardware and compute raster), cornell's LPV frame, and issue 15's hair frames with camera translucency.
# Usage: bench/merged_check.sh PENUMBRA ASSETS_DIR OUT_DIR
set -euo pipefail
bin=$1 assets=$2 out=$3
. "$(dirname "$0")/lib.sh"
run sponza_1920x1080_full-frame-merged $sponza $full
run sponza_1920x1080_full-frame-merged-compute $sponza $full --raster compute
run vc_1920x1080_full-frame-merged $vc $full
run vc_1920x1080_full-frame-merged-compute $vc $full --raster compute
run cornell_1920x1080_gi-lpv-merged cornell --width 1920 --height 1080 --gi lpv
for n in 25000 100000; do
  run hair-${n}_1920x1080_dsm-merged hair --strands $n --shadow dsm --dsm-res 2048 --width 1920 --height 1080
done
