#!/usr/bin/env bash
# Accuracy of GI variants on the GI suite's five views (cornell, street, room, Sponza, VC) against the
# suite's path-traced references: first `eval --suite` (which renders the references into OUT/refs,
# or reuses them, and scores the defaults), then for each variant `render --shadow hard --aov indirect`
# of the suite's 32 still frames (the GI history settled) and `compare` of the last with the suite's
# mask, as the suite scores its defaults: relative L1 and bias per view.
#   VARIANTS  NAME:OPTIONS ... (options joined by commas; default: the defaults alone)
#   GI        rsm or lpv (default lpv);  SCENES  which views (default all five)
# Usage: bench/gi_variants.sh PENUMBRA ASSETS OUT
#   e.g. GI=rsm VARIANTS="s150:--rsm-samples,150 s600:--rsm-samples,600" bench/gi_variants.sh build/penumbra ../shared/assets /tmp/gi
set -euo pipefail
if [ $# -lt 3 ]; then sed -n "2,9p" "$0"; exit 2; fi
bin=$1 assets=$2 out=$3
# shellcheck source=bench/views.sh
. "$(dirname "$0")/views.sh"
mkdir -p "$out"
refs=$out/refs
scenes=${SCENES:-cornell street room sponza vc}
"$bin" eval --suite --reference "$refs" --assets "$assets" --scenes "${scenes// /,}" --json "$out/suite.json" \
  > "$out/suite.txt" 2>&1
grep -E "^\| (cornell|street|room|sponza|vc)|ceiling" "$out/suite.txt" || cat "$out/suite.txt"
# The suite's sizes of each view (the references are rendered at these).
declare -A view=([cornell]="cornell --width 128 --height 96" [street]="street --width 128 --height 72"
                 [room]="room --width 128 --height 72" [sponza]="$sponza --width 128 --height 72"
                 [vc]="$vc --width 128 --height 72")
for v in ${VARIANTS:-default:}; do
  name=${v%%:*} opts=${v#*:} opts=${opts//,/ }
  for scene in $scenes; do
    # shellcheck disable=SC2086
    timeout 300 "$bin" render ${view[$scene]} --shadow hard --gi "${GI:-lpv}" --aov indirect --exposure 1 --sky none \
      --sequence 32 --no-motion $opts -o "$out/$scene-$name-%04d.exr" > "$out/$scene-$name.log" 2>&1 ||
      { echo "$scene $name FAILED"; continue; }
    mv "$out/$scene-$name-0031.exr" "$out/$scene-$name.exr" && rm -f "$out/$scene-$name"-00*.exr
    "$bin" compare "$out/$scene-$name.exr" "$refs/$scene-seed1/indirect.exr" --mask "$refs/$scene-seed1/mask.exr" \
      --json -o "$out/error-$scene-$name.png" > "$out/accuracy-$scene-$name.json"
    python3 -c "import json,sys; j=json.load(open(sys.argv[1])); print(sys.argv[2], 'rel_l1 %.3f bias %+.1f%%' % (j['rel_l1'], 100*j['relative_bias']))" \
      "$out/accuracy-$scene-$name.json" "$scene $name"
    rm "$out/$scene-$name.exr"
  done
done
