#!/usr/bin/env bash
# Issue 11's loop measurements on the GPU machine: Sponza and VC full frames with the old loop (each
# frame waited for) and frames in flight; JSON per run into OUTDIR. Usage: bench/frame_loop.sh BIN ASSETS OUTDIR
set -euo pipefail
bin=$1 assets=$2 out=$3
mkdir -p "$out"
full="--shadow pcf --cascades 4 --shadow-res 2048 --gi lpv --lpv-res 32 --lpv-iterations 8 --width 1920 --height 1080"
sponza="$assets/sponza/glTF/Sponza.gltf --camera -9,1.7,0.3,6,4.5,0,0,1,0,70 --light directional,0.1,-1,0.2,20"
vc="$assets/VC/glTF/VC.gltf --camera 14,9,16,0,1.5,0,0,1,0,50"
for fif in 1 2; do
  # shellcheck disable=SC2086
  "$bin" bench $sponza $full --frames 200 --warmup 30 --frames-in-flight $fif --json "$out/sponza_1920x1080_full-frame_fif$fif.json" | tail -6
  # shellcheck disable=SC2086
  "$bin" bench $vc $full --frames 200 --warmup 30 --frames-in-flight $fif --json "$out/vc_1920x1080_full-frame_fif$fif.json" | tail -6
done
