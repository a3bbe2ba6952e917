#!/usr/bin/env bash
# 2026-11-26 (session 26): the DSM without linked lists (two-step build into per-texel runs, depth
# buckets cut at the list cap, one workgroup per texel in the resolve).
# Usage (device): bench/hair_v22.sh PENUMBRA ASSETS_DIR OUT_DIR
set -euo pipefail
bin=$1 assets=$2 out=$3
. "$(dirname "$0")/lib.sh"
for n in 25000 100000; do
  run hair_1920x1080_dsm-$n $hair --shadow dsm --strands $n
  run hair_1920x1080_dom-$n $hair --shadow dom --strands $n
  run hair_1920x1080_dsm-depth-test-$n $hair --shadow dsm --strands $n --dsm-depth-test on
done
run hair_1920x1080_dsm-links-25000 $hair --shadow dsm --strands 25000 --dsm-lookup links
summarize
"$bin" render hair --shadow dsm --strands 100000 --dsm-res 2048 --width 1920 --height 1080 --frames 3 \
  -o "$out/hair-dsm-100k.png" 2>&1 | grep -E "dsm:|warn" || true
