#!/usr/bin/env bash
# 2026-11-26 (session 25): the RSM interpolation taking two of the four nearest low-res gathers where a
# cell is smaller than the RSM's texel (penumbra) against always three (penumbra3, the build before),
# at 1080p: cost, the fallback share, and each one's indirect light against the full gather (every
# pixel gathered with the same 400 samples: what interpolation approximates); then the GI suite.
# Usage (device): bench/rsm_interp_ab.sh DIR_WITH_BINARIES ASSETS_DIR OUT_DIR
set -uo pipefail
dir=$1 assets=$2 out=$3
. "$(dirname "$0")/lib.sh"
for s in cornell vc sponza; do
  case $s in cornell) args=cornell;; vc) args=$vc;; sponza) args=$sponza;; esac
  for v in 3 2; do
    bin=$dir/penumbra; [ $v = 3 ] && bin=$dir/penumbra3
    run ${s}_rsm_interp$v $args --width 1920 --height 1080 --gi rsm
    "$bin" render $args --width 1920 --height 1080 --gi rsm --aov indirect -o $out/${s}_$v.exr 2>&1 | grep "fallback:" | sed "s/^/${s} interp$v: /"
  done
  # The full gather with a pattern of another seed: independent of the fallback pixels' own samples.
  "$dir/penumbra" render $args --width 1920 --height 1080 --gi rsm --rsm-mode full --rsm-seed 7 --aov indirect -o $out/${s}_full.exr > /dev/null 2>&1
  for v in 3 2; do
    "$dir/penumbra" compare $out/${s}_$v.exr $out/${s}_full.exr 2>&1 | grep -E "rel L1|mean bias" | sed "s/^/${s} interp$v vs full: /"
  done
  "$dir/penumbra" compare $out/${s}_2.exr $out/${s}_3.exr 2>&1 | grep -E "rel L1|differing" | sed "s/^/${s} interp2 vs interp3: /"
  rm -f $out/${s}_*.exr
done
summarize
[ "${SKIP_SUITE:-0}" = 1 ] && exit 0
bin=$dir/penumbra
"$bin" eval --suite --reference /tmp/gicache --assets "$assets" --json "$out/gi-suite.json" > "$out/gi-suite.txt" 2>&1
grep -E "^\| (cornell|street|room|sponza|vc)" "$out/gi-suite.txt"
