#!/usr/bin/env bash
# 2026-11-26: the compute rasterizer stores its shadow maps into R32_SFLOAT (no copy into D32), every
# filter compares by hand from a gather, LPV injection sums a subgroup's VPLs per cell. Two binaries
# interleaved twice on one machine (--raster auto: the compute rasterizer on the H100; cold frames):
# issue 14's full frames (its fixed LPV options, then LPV's defaults), cornell's LPV and RSM frames,
# issue 15's hair frame; then the final images of both binaries compared.
# Usage (device): bench/speed_v5.sh OLD_PENUMBRA NEW_PENUMBRA ASSETS_DIR OUT_DIR
set -euo pipefail
old=$1 new=$2 assets=$3 out=$4
bin=$new
. "$(dirname "$0")/lib.sh"
newLpv="--shadow pcf --cascades 4 --shadow-res 2048 --gi lpv --width 1920 --height 1080"
for round in 1 2; do
  for side in old new; do
    bin=${!side}
    run sponza_1920x1080_full-frame-$side-$round $sponza $full --raster auto
    run vc_1920x1080_full-frame-$side-$round $vc $full --raster auto
    run sponza_1920x1080_full-frame-new-lpv-$side-$round $sponza $newLpv --raster auto
    run vc_1920x1080_full-frame-new-lpv-$side-$round $vc $newLpv --raster auto
    run cornell_1920x1080_gi-lpv-$side-$round cornell --width 1920 --height 1080 --gi lpv --raster auto
    run cornell_1920x1080_gi-rsm-$side-$round cornell --width 1920 --height 1080 --gi rsm --raster auto
    run hair_1920x1080_dsm-25000-$side-$round hair --dsm-res 2048 --width 1920 --height 1080 --shadow dsm --strands 25000
  done
done
for side in old new; do
  bin=${!side}
  for scene in sponza vc; do
    "$bin" render ${!scene} $techniques --raster auto --width 960 --height 540 -o "$out/${scene}_$side.exr" > /dev/null 2>&1
  done
done
for scene in sponza vc; do
  echo "== $scene: new against old"; "$new" compare "$out/${scene}_new.exr" "$out/${scene}_old.exr"
done
rm -f "$out"/*.exr
summarize
