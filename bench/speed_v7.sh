#!/usr/bin/env bash
# 2026-11-26, session 25, end: issue 15's hair frames (DSM by binary search, the default; the link
# walk; DSM with a bilinear filter; DOM), issue 13's GI frames (RSM gather with 4 lanes per receiver),
# issue 14's target frames (unchanged passes, a regression check), then the GI suite.
# Usage (device): bench/speed_v7.sh PENUMBRA ASSETS_DIR OUT_DIR
set -euo pipefail
bin=$1 assets=$2 out=$3
. "$(dirname "$0")/lib.sh"
for n in 25000 100000; do
  run hair_1920x1080_dsm-$n $hair --shadow dsm --strands $n
  run hair_1920x1080_dsm-links-$n $hair --shadow dsm --strands $n --dsm-lookup links
  run hair_1920x1080_dsm-filter0-$n $hair --shadow dsm --strands $n --dsm-filter 0
  run hair_1920x1080_dom-$n $hair --shadow dom --strands $n
done
for g in rsm lpv; do
  run cornell_1920x1080_gi-$g cornell --width 1920 --height 1080 --gi $g
  run vc_1920x1080_gi-$g $vc --width 1920 --height 1080 --gi $g
  run sponza_1920x1080_gi-$g $sponza --width 1920 --height 1080 --gi $g
done
for scene in sponza vc; do run ${scene}_1920x1080_full-frame ${!scene} $full; done
summarize
"$bin" eval --suite --reference "$out/gi-cache" --assets "$assets" --json "$out/gi-suite-h100.json" > "$out/gi-suite-h100.txt" 2>&1 || echo "FAILED eval"
rm -rf "$out/gi-cache"
cat "$out/gi-suite-h100.txt"
