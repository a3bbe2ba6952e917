#!/usr/bin/env bash
# --raster hardware vs compute on the GPU machine: Sponza and VC, 4 cascades of 2048^2 with PCF at 1080p.
# Usage: bench/raster_compare.sh BIN ASSETS OUTDIR
set -euo pipefail
bin=$1 assets=$2 out=$3
mkdir -p "$out"
common="--shadow pcf --cascades 4 --shadow-res 2048 --width 1920 --height 1080 --frames 100 --warmup 20"
sponza="$assets/sponza/glTF/Sponza.gltf --camera -9,1.7,0.3,6,4.5,0,0,1,0,70 --light directional,0.1,-1,0.2,20"
vc="$assets/VC/glTF/VC.gltf --camera 14,9,16,0,1.5,0,0,1,0,50"
for raster in hardware compute; do
  # shellcheck disable=SC2086
  "$bin" bench $sponza $common --raster $raster --json "$out/sponza_1920x1080_shadow-$raster.json" | grep -E "shadow|frame \(GPU"
  # shellcheck disable=SC2086
  "$bin" bench $vc $common --raster $raster --json "$out/vc_1920x1080_shadow-$raster.json" | grep -E "shadow|frame \(GPU"
done
