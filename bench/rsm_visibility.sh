#!/usr/bin/env bash
# Issue 13, RSM voxel visibility: the gather passes' cost at 1080p (cornell, VC, Sponza; --raster auto,
# cold frames) for the previous visibility (depth: far samples against the RSM) and for voxels with
# 32, 64, 128 and 400 of the 400 samples tested (or VARIANTS); then each variant's accuracy on the GI
# suite's five views against the cached path-traced references (render --aov indirect + compare, as eval --suite).
# Usage: bench/rsm_visibility.sh PENUMBRA ASSETS_DIR REFERENCE_DIR OUT_DIR
set -euo pipefail
bin=$1 assets=$2 refs=$3 out=$4
. "$(dirname "$0")/lib.sh"
# A variant is NAME:OPTIONS, its options joined by commas (--opt=value).
variants=(${VARIANTS:-depth:--rsm-visibility=depth vox32:--rsm-visibility-rays=32 vox64:--rsm-visibility-rays=64
          vox128:--rsm-visibility-rays=128 vox400:--rsm-visibility-rays=400})
for v in "${variants[@]}"; do
  name=${v%%:*} opts=${v#*:} opts=${opts//,/ }
  run cornell_1920x1080_gi-rsm-$name cornell --width 1920 --height 1080 --gi rsm --raster auto $opts
  run vc_1920x1080_gi-rsm-$name $vc --width 1920 --height 1080 --gi rsm --raster auto $opts
  run sponza_1920x1080_gi-rsm-$name $sponza --width 1920 --height 1080 --gi rsm --raster auto $opts
done
# The suite's views (src/eval/suite.cpp): scene arguments, size.
declare -A view=([cornell]="cornell --width 128 --height 96" [street]="street --width 128 --height 72"
                 [room]="room --width 128 --height 72" [sponza]="$sponza --width 128 --height 72"
                 [vc]="$vc --width 128 --height 72")
for v in "${variants[@]}"; do
  name=${v%%:*} opts=${v#*:} opts=${opts//,/ }
  for scene in cornell street room sponza vc; do
    "$bin" render ${view[$scene]} --shadow hard --gi rsm --aov indirect $opts -o "$out/$scene-$name.exr" >/dev/null 2>&1
    "$bin" compare "$out/$scene-$name.exr" "$refs/$scene-seed1/indirect.exr" --mask "$refs/$scene-seed1/mask.exr" \
      --json > "$out/accuracy-$scene-$name.json"
    python3 -c "import json,sys; j=json.load(open(sys.argv[1])); print(sys.argv[2], 'rel_l1 %.3f bias %+.1f%%' % (j['rel_l1'], 100*j['relative_bias']))" \
      "$out/accuracy-$scene-$name.json" "$scene $name"
    rm "$out/$scene-$name.exr"
  done
done
summarize
