#!/usr/bin/env bash
# A/B: interpolation accepting 3 of the 4 nearest (penumbra3) against 2 (penumbra).
set -uo pipefail
dir=$1 assets=$2 out=$3
mkdir -p $out
. bench/lib.sh
for v in 3 2; do
  bin=$dir/penumbra; [ $v = 3 ] && bin=$dir/penumbra3
  for s in cornell vc sponza; do
    case $s in cornell) args=cornell;; vc) args=$vc;; sponza) args=$sponza;; esac
    run ${s}_rsm_valid$v $args --width 1920 --height 1080 --gi rsm
    "$bin" render $args --width 1920 --height 1080 --gi rsm -o $out/${s}_valid$v.png 2>&1 | grep "fallback:" | sed "s/^/${s} valid$v: /"
  done
  "$bin" eval --suite --reference /tmp/gicache --assets "$assets" --json "$out/gi-suite-valid$v.json" > "$out/gi-suite-valid$v.txt" 2>&1
  grep -E "^\| (cornell|street|room|sponza|vc)" "$out/gi-suite-valid$v.txt" | sed "s/^/valid$v /"
done
summarize
