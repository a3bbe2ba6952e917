#!/usr/bin/env bash
# The default RSM gather before and after issue 13's third round on one machine: two binaries,
# interleaved twice, cornell, VC and Sponza at 1080p (--gi rsm --raster auto, cold frames).
# Usage: bench/ab_default_gather.sh OLD_PENUMBRA NEW_PENUMBRA ASSETS_DIR OUT_DIR
set -euo pipefail
old=$1 new=$2 assets=$3 out=$4
bin=$new
. "$(dirname "$0")/lib.sh"
for round in 1 2; do
  for side in old new; do
    bin=${!side}
    run cornell_1920x1080_gi-rsm-$side-$round cornell --width 1920 --height 1080 --gi rsm --raster auto
    run vc_1920x1080_gi-rsm-$side-$round $vc --width 1920 --height 1080 --gi rsm --raster auto
    run sponza_1920x1080_gi-rsm-$side-$round $sponza --width 1920 --height 1080 --gi rsm --raster auto
  done
done
