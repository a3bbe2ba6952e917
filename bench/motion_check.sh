#!/usr/bin/env bash
# Motion on the GPU machine (issue 12): the stability table (cornell's default motion, VC and Sponza
# with a moving sun; every shadow filter and GI mode, the path tracer's floor on the host's cores),
# and `bench` of Sponza's full frame with a moving sun (CPU and GPU ms per frame, geometry uploads)
# beside the same frame standing still.
# Usage: bench/motion_check.sh PENUMBRA ASSETS_DIR OUT_DIR
set -euo pipefail
bin=$1 assets=$2 out=$3
mkdir -p "$out"
sponza="$assets/sponza/glTF/Sponza.gltf --camera -9,1.7,0.3,6,4.5,0,0,1,0,70 --light directional,0.1,-1,0.2,20"
vc="$assets/VC/glTF/VC.gltf --camera 14,9,16,0,1.5,0,0,1,0,50 --light directional,0.3,-1,0.4,6"
# Sponza's sun (azimuth 63.4, elevation 77.4 degrees) turning 1.5 and sinking 0.75 degrees per frame at 30 fps.
sponzaSun="--sun-path 63.4,77.4,75.4,71.4,0.26667"
vcSun="--sun-path 53.1,63.4,65.1,57.4,0.26667"
stab="stability --frames 8 --all --reference-max-spp 2048"
sponzaCamera="--camera-keys 0,-9,1.7,0.3,6,4.5,0;0.26667,-8.2,1.7,0.5,6.8,4.5,0.2"
"$bin" $stab cornell --json "$out/stability_cornell.json" > "$out/stability_cornell.txt" 2>&1 || echo "FAILED cornell"
"$bin" $stab $vc $vcSun --json "$out/stability_vc.json" > "$out/stability_vc.txt" 2>&1 || echo "FAILED vc"
"$bin" $stab $sponza $sponzaSun --json "$out/stability_sponza.json" > "$out/stability_sponza.txt" 2>&1 || echo "FAILED sponza"
"$bin" $stab $sponza $sponzaCamera --json "$out/stability_sponza_camera.json" > "$out/stability_sponza_camera.txt" 2>&1 ||
  echo "FAILED sponza camera"
full="--shadow pcf --cascades 4 --shadow-res 2048 --gi lpv --lpv-res 32 --lpv-iterations 8 --width 1920 --height 1080"
frames="--frames 60 --warmup 10"
# The bench's sun turns over all 70 frames (2.4 s at 30 fps), so no frame of it stands still.
"$bin" bench $sponza $full $frames --sun-path 63.4,77.4,98.4,59.9,2.4 --json "$out/sponza_1920x1080_full-frame_moving-sun.json" \
  > "$out/sponza_moving-sun.txt" 2>&1 || echo "FAILED bench moving"
"$bin" bench $sponza $full $frames --json "$out/sponza_1920x1080_full-frame_still.json" \
  > "$out/sponza_still.txt" 2>&1 || echo "FAILED bench still"
tail -n 25 "$out"/*.txt
