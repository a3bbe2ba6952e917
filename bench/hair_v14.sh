#!/usr/bin/env bash
# 2026-11-26 (session 25), fifth run: the bounded DSM build (front, count, cut, then the build of
# what the caps keep) with 8 depth buckets (penumbra) and 16 (penumbra16), against --dsm-bounded-build off.
# (The bounded build was not kept: bench/results/2026-11-26-h100/session25/hair_v14/
# bounded-build.patch is its code.)
# Usage (device): bench/hair_v14.sh DIR_WITH_BINARIES ASSETS_DIR OUT_DIR
set -euo pipefail
dir=$1 assets=$2 out=$3
bin=$dir/penumbra
. "$(dirname "$0")/lib.sh"
hair="hair --dsm-res 2048 --width 1920 --height 1080 --shadow dsm"
for n in 25000 100000; do
  bin=$dir/penumbra
  run hair${n}_unbounded $hair --strands $n --dsm-bounded-build off
  run hair${n}_bounded8 $hair --strands $n
  bin=$dir/penumbra16
  run hair${n}_bounded16 $hair --strands $n
  "$bin" render $hair --strands $n -o "$out/hair${n}.png" 2>&1 | grep -E "dsm:|warning"
done
summarize
