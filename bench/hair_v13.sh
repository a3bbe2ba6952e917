#!/usr/bin/env bash
# 2026-11-26 (session 25), fourth run: the camera lists' pool at 16 nodes per pixel (8 dropped 44%
# of 100k strands' camera fragments), the DSM filter's width (--dsm-filter 0: bilinear, 4 taps
# against 9), and each frame's list statistics (`render` prints them).
# Usage (device): bench/hair_v13.sh PENUMBRA ASSETS_DIR OUT_DIR
set -euo pipefail
bin=$1 assets=$2 out=$3
. "$(dirname "$0")/lib.sh"
for n in 25000 100000; do
  run hair${n}_dsm $hair --shadow dsm --strands $n
  run hair${n}_dsm_filter0 $hair --shadow dsm --strands $n --dsm-filter 0
  run hair${n}_dom $hair --shadow dom --strands $n
  "$bin" render $hair --shadow dsm --strands $n -o "$out/hair${n}.png" > "$out/render_hair${n}.txt" 2>&1
  grep -E "translucency:|dsm:|warning" "$out/render_hair${n}.txt"
done
summarize
