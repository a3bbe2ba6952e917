#!/usr/bin/env bash
# Renders the same matrix of scenes and settings with two penumbra binaries and compares the EXR
# images byte for byte: every --gi under every --shadow, and both --camera-path and --raster values
# under every --gi, on cornell, hair, VC and Sponza (small images, lavapipe unless told otherwise).
# Usage: scripts/compare-renders.sh OLD_BINARY NEW_BINARY ASSETS_DIR OUT_DIR
# Prints one line per differing image and a count; exits non-zero when any image differs.
set -euo pipefail
old=$1 new=$2 assets=$3 out=$4
mkdir -p "$out/old" "$out/new"
export VK_DRIVER_FILES=${VK_DRIVER_FILES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
scenes=(cornell hair "$assets/VC/glTF/VC.gltf" "$assets/sponza/glTF/Sponza.gltf")
cases=()
for gi in none rsm lpv; do
  for shadow in hard pcf pcss vsm evsm msm pcf,dsm; do cases+=("--gi $gi --shadow $shadow"); done
  cases+=("--gi $gi --camera-path gbuffer" "--gi $gi --raster compute" "--gi $gi --raster hardware")
done
count=0 differ=0
for scene in "${scenes[@]}"; do
  [ -e "$scene" ] || [ "${scene#*/}" = "$scene" ] || { echo "skip: $scene not found"; continue; }
  for args in "${cases[@]}"; do
    name=$(basename "${scene%.gltf}")_$(echo "$args" | tr -c 'a-z0-9' '_').exr
    for bin in old new; do
      b=$old; [ $bin = new ] && b=$new
      # shellcheck disable=SC2086
      "$b" render "$scene" $args --width 96 --height 64 --shadow-res 256 --rsm-res 64 --lpv-rsm-res 256 \
        --lpv-vpl-res 64 -q -o "$out/$bin/$name" >/dev/null 2>"$out/$bin/$name.log" || echo "failed: $bin $scene $args"
    done
    count=$((count + 1))
    if ! cmp -s "$out/old/$name" "$out/new/$name"; then differ=$((differ + 1)); echo "differs: $scene $args"; fi
  done
done
echo "$count images compared, $differ differ"
[ "$differ" -eq 0 ]
