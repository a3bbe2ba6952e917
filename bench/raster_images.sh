#!/usr/bin/env bash
# Images of --raster compute against --raster hardware on the GPU machine (its raster hardware is the
# reference there): Sponza and VC at 1080p, 4 cascades of 2048^2 with PCF, the shadow AOV and the
# final image with LPV, for each binary given (e.g. before and after a change to the compute rasterizer).
# Usage (device): bench/raster_images.sh ASSETS OUT_DIR PENUMBRA... (the first also compares them all)
set -euo pipefail
assets=$1 out=$2; shift 2
bin=$1 cmp=$1
. "$(dirname "$0")/lib.sh"
n=0
for bin in "$@"; do
  n=$((n + 1))
  for scene in sponza vc; do
    for aov in shadow final; do
      for raster in hardware compute; do
        "$bin" render ${!scene} $full --aov $aov --raster $raster -o "$out/$scene-$aov-$raster-$n.exr" > /dev/null 2>&1
      done
      echo "== binary $n ($bin), $scene, $aov: compute against hardware"
      "$cmp" compare "$out/$scene-$aov-compute-$n.exr" "$out/$scene-$aov-hardware-$n.exr" | grep -E "rel L2|max error|differing"
    done
  done
done
rm -f "$out"/*.exr
