#!/usr/bin/env bash
# Issue 13: what the interpolation's two-of-four rule costs in accuracy at 1080p. Against a 3200-sample
# full gather (the indirect AOV, hard shadows): 400-sample full gathers, the interpolated path of NEW,
# and that of OTHER (the same binary with another interpolation rule), on cornell, VC and Sponza.
# Usage (device): bench/rsm_rule_accuracy.sh NEW OTHER ASSETS_DIR OUT_DIR
set -euo pipefail
new=$1 other=$2 assets=$3 out=$4
bin=$new
. "$(dirname "$0")/lib.sh"
declare -A view=([cornell]="cornell" [sponza]="$sponza" [vc]="$vc")
for s in cornell vc sponza; do
  common="${view[$s]} --width 1920 --height 1080 --shadow hard --gi rsm --aov indirect"
  "$new" render $common --rsm-mode full --rsm-samples 3200 -o "$out/$s-ref.exr" > "$out/$s-ref.log" 2>&1
  "$new" render $common --rsm-mode full -o "$out/$s-full400.exr" > "$out/$s-full400.log" 2>&1
  "$new" render $common -o "$out/$s-new.exr" > "$out/$s-new.log" 2>&1
  "$other" render $common -o "$out/$s-other.exr" > "$out/$s-other.log" 2>&1
  for v in full400 new other; do
    "$new" compare "$out/$s-$v.exr" "$out/$s-ref.exr" --json -o "$out/err-$s-$v.png" > "$out/acc-$s-$v.json"
    python3 -c "import json,sys; j=json.load(open(sys.argv[1])); print(sys.argv[2], 'rel_l1 %.4f bias %+.2f%%' % (j['rel_l1'], 100*j['relative_bias']))" \
      "$out/acc-$s-$v.json" "$s $v"
  done
  rm -f "$out"/$s-*.exr
done
