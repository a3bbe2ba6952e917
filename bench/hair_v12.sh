#!/usr/bin/env bash
# 2026-11-26 (session 25), third run: a texel's (and pixel's) fragments on DSM_CHAINS lists walked
# side by side by the resolve and the composite; the depth-tested build under the compute ribbon
# raster; deep opacity maps beside them.
# (PENUMBRA_OIT_EXP was read by an uncommitted experiment build.)
# Usage (device): bench/hair_v12.sh PENUMBRA ASSETS_DIR OUT_DIR
set -euo pipefail
bin=$1 assets=$2 out=$3
. "$(dirname "$0")/lib.sh"
for n in 25000 100000; do
  run hair${n}_dsm $hair --shadow dsm --strands $n
  run hair${n}_dsm_depth-test $hair --shadow dsm --strands $n --dsm-depth-test on
  run hair${n}_dom $hair --shadow dom --strands $n
done
PENUMBRA_OIT_EXP=1 run hair25000_nodsm $hair --shadow dsm --strands 25000
summarize
