#!/usr/bin/env bash
# Issue 13: GI variants on the suite's five views against its references (rendered here, as `eval --suite`
# caches them), each `render --shadow hard --aov indirect` + `compare`, as the suite scores its defaults.
# VARIANTS: NAME:OPTIONS ... (options joined by commas); GI: rsm or lpv (default lpv); SCENES: which views.
# Usage (device): bench/gi_variants.sh PENUMBRA ASSETS_DIR OUT_DIR
set -euo pipefail
bin=$1 assets=$2 out=$3
. "$(dirname "$0")/lib.sh"
refs=$out/refs
scenes=${SCENES:-cornell street room sponza vc}
"$bin" eval --suite --reference "$refs" --assets "$assets" --scenes "${scenes// /,}" --json "$out/suite.json" \
  > "$out/suite.txt" 2>&1
grep -E "^\| (cornell|street|room|sponza|vc)|ceiling" "$out/suite.txt" || cat "$out/suite.txt"
declare -A view=([cornell]="cornell --width 128 --height 96" [street]="street --width 128 --height 72"
                 [room]="room --width 128 --height 72" [sponza]="$sponza --width 128 --height 72"
                 [vc]="$vc --width 128 --height 72")
for v in ${VARIANTS:-default:}; do
  name=${v%%:*} opts=${v#*:} opts=${opts//,/ }
  for scene in $scenes; do
    timeout 300 "$bin" render ${view[$scene]} --shadow hard --gi ${GI:-lpv} --aov indirect $opts \
      -o "$out/$scene-$name.exr" > "$out/$scene-$name.log" 2>&1 || { echo "$scene $name FAILED"; continue; }
    "$bin" compare "$out/$scene-$name.exr" "$refs/$scene-seed1/indirect.exr" --mask "$refs/$scene-seed1/mask.exr" \
      --json -o "$out/error-$scene-$name.png" > "$out/accuracy-$scene-$name.json"
    python3 -c "import json,sys; j=json.load(open(sys.argv[1])); print(sys.argv[2], 'rel_l1 %.3f bias %+.1f%%' % (j['rel_l1'], 100*j['relative_bias']))" \
      "$out/accuracy-$scene-$name.json" "$scene $name"
    rm "$out/$scene-$name.exr"
  done
done
