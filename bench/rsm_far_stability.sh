#!/usr/bin/env bash
# Issue 13: RSM flicker under moving lights, the defaults against other options (VARIANTS: NAME:OPTIONS, options
# joined by commas; by default session 28's far disc, fixed radii, 400 samples): `stability` without the path
# tracer, the motions of README "Temporal stability".
# Usage: bench/rsm_far_stability.sh PENUMBRA OUT_DIR (assets in ../shared/assets)
bin=$1; out=$2; mkdir -p $out
assets=../shared/assets
sponza="$assets/sponza/glTF/Sponza.gltf --camera -9,1.7,0.3,6,4.5,0,0,1,0,70 --light directional,0.1,-1,0.2,20"
vc="$assets/VC/glTF/VC.gltf --camera 14,9,16,0,1.5,0,0,1,0,50 --light directional,0.3,-1,0.4,6"
for entry in default: ${VARIANTS:-old:--rsm-far,disc,--rsm-radii,fixed,--rsm-samples,400}; do
  k=${entry%%:*} o=${entry#*:} o=${o//,/ }
  $bin stability --frames 8 --gi rsm --shadow pcf --no-reference $o cornell > $out/cornell-$k.txt 2>&1
  $bin stability --frames 8 --gi rsm --shadow pcf --no-reference $o $vc --sun-path 53.1,63.4,65.1,57.4,0.26667 > $out/vc-$k.txt 2>&1
  $bin stability --frames 8 --gi rsm --shadow pcf --no-reference $o $sponza --sun-path 63.4,77.4,75.4,71.4,0.26667 > $out/sponza-$k.txt 2>&1
  $bin stability --frames 8 --gi rsm --shadow pcf --no-reference $o $sponza \
    --camera-keys "0,-9,1.7,0.3,6,4.5,0;0.26667,-8.2,1.7,0.5,6.8,4.5,0.2" > $out/sponza-camera-$k.txt 2>&1
done
for f in $out/*.txt; do echo "$(basename $f) $(grep rsm $f)"; done
