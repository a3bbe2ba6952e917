#!/usr/bin/env bash
# A/B of two penumbra binaries on issue 15's hair frames (DSM and DOM, 25k and 100k strands), each
# pair on the same warm machine one after the other, then the new binary's 100k image.
# Usage (device): bench/hair_ab.sh BASE NEW ASSETS_DIR OUT_DIR [extra bench args for NEW]
set -euo pipefail
base=$1 new=$2 assets=$3 out=$4; shift 4
bin=$new
. "$(dirname "$0")/lib.sh"
for n in 25000 100000; do
  for shadow in dsm dom; do
    bin=$base run base-hair_1920x1080_$shadow-$n $hair --shadow $shadow --strands $n
    bin=$new run hair_1920x1080_$shadow-$n $hair --shadow $shadow --strands $n "$@"
  done
done
summarize
"$new" render hair --shadow dsm --strands 100000 --dsm-res 2048 --width 1920 --height 1080 --frames 3 \
  -o "$out/hair-dsm-100k.png" "$@" 2>&1 | grep -E "dsm:|warn" || true
