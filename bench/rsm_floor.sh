#!/usr/bin/env bash
# Issue 13, session 28: how close can a gather of the RSM come to the path tracer on Sponza and VC (targets rel L1
# <= 0.25)? The suite's references (rendered here), then the suite's views (128x72) gathered in full at every
# pixel with many samples (unbiased radii), with and without every sample's visibility walked through the
# occupancy volume, at RSM resolutions up to 2048: what is left when sampling noise and light through walls are
# gone is the RSM's own error (what it represents of the one-bounce light).
# Usage (device): bench/rsm_floor.sh PENUMBRA ASSETS_DIR OUT_DIR
set -euo pipefail
bin=$1 assets=$2 out=$3
. "$(dirname "$0")/lib.sh"
refs=$out/refs
# VARIANTS (NAME:OPTIONS ..., options joined by commas), SCENES and KEEP (keep the EXR files) may be set.
"$bin" eval --suite --reference "$refs" --assets "$assets" --scenes sponza,vc --json "$out/suite.json" > "$out/suite.txt" 2>&1
grep -E "^\| (sponza|vc)" "$out/suite.txt" || cat "$out/suite.txt"
declare -A view=([sponza]="$sponza --width 128 --height 72" [vc]="$vc --width 128 --height 72")
full="--rsm-mode full --rsm-radii shifted"
variants=(${VARIANTS:-
  "default:"
  "full4k-none:$full --rsm-samples 4096 --rsm-visibility none"
  "full4k-vox:$full --rsm-samples 4096 --rsm-visibility voxels --rsm-visibility-rays 4096"
  "full16k-vox:$full --rsm-samples 16384 --rsm-visibility voxels --rsm-visibility-rays 16384"
  "full16k-vox-res1024:$full --rsm-samples 16384 --rsm-visibility voxels --rsm-visibility-rays 16384 --rsm-res 1024"
  "full16k-vox-res2048:$full --rsm-samples 16384 --rsm-visibility voxels --rsm-visibility-rays 16384 --rsm-res 2048"
  "full16k-vox256:$full --rsm-samples 16384 --rsm-visibility voxels --rsm-visibility-rays 16384 --rsm-voxel-res 256"
})
for v in "${variants[@]}"; do
  name=${v%%:*} opts=${v#*:} opts=${opts//,/ }  # options given joined by commas
  for scene in ${SCENES:-sponza vc}; do
    t0=$(date +%s.%N)
    timeout 300 "$bin" render ${view[$scene]} --shadow hard --gi rsm --aov indirect $opts -o "$out/$scene-$name.exr" \
      > "$out/$scene-$name.log" 2>&1 || { echo "$scene $name FAILED"; continue; }
    t1=$(date +%s.%N)
    "$bin" compare "$out/$scene-$name.exr" "$refs/$scene-seed1/indirect.exr" --mask "$refs/$scene-seed1/mask.exr" \
      --json -o "$out/error-$scene-$name.png" > "$out/accuracy-$scene-$name.json"
    python3 -c "import json,sys; j=json.load(open(sys.argv[1])); print(sys.argv[2], 'rel_l1 %.3f bias %+.1f%%' % (j['rel_l1'], 100*j['relative_bias']), sys.argv[3])" \
      "$out/accuracy-$scene-$name.json" "$scene $name" "$(python3 -c "print(round($t1 - $t0, 1))") s"
    [ -n "${KEEP:-}" ] || rm "$out/$scene-$name.exr"
  done
done
