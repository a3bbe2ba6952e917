#!/usr/bin/env bash
# Renders the same matrix of scenes and settings with two penumbra binaries and compares the EXR
# images byte for byte: every --gi under every --shadow, both --camera-path and both --raster values
# (all combinations), on cornell, hair, VC and Sponza (small images, lavapipe unless told otherwise).
# Usage: scripts/compare-renders.sh OLD_BINARY NEW_BINARY ASSETS_DIR OUT_DIR
# The environment narrows or widens the matrix (space-separated lists):
#   SCENES        built-in names, or paths under ASSETS_DIR (default: cornell hair VC/glTF/VC.gltf
#                 sponza/glTF/Sponza.gltf); a path that is missing is skipped with a line
#   GIS, SHADOWS, CAMERA_PATHS, RASTERS   the values of --gi, --shadow, --camera-path, --raster
#   RENDER_ARGS   what every render adds (default: a small image and small maps)
#   JOBS          renders at a time (default 1)
# Prints one line per differing or failed image and the counts; exits non-zero when any image differs
# (a case that both binaries refuse with the same message is counted apart).
set -euo pipefail
old=$1 new=$2 assets=$3 out=$4
mkdir -p "$out/old" "$out/new"
export VK_DRIVER_FILES=${VK_DRIVER_FILES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
read -ra scenes <<<"${SCENES:-cornell hair VC/glTF/VC.gltf sponza/glTF/Sponza.gltf}"
read -ra render_args <<<"${RENDER_ARGS:---width 96 --height 64 --shadow-res 256 --rsm-res 64 --lpv-rsm-res 256 --lpv-vpl-res 64}"
max_jobs=${JOBS:-1}
cases=()
for gi in ${GIS:-none rsm lpv}; do
  for shadow in ${SHADOWS:-hard pcf pcss vsm evsm msm pcf,dsm}; do
    for path in ${CAMERA_PATHS:-visibility gbuffer}; do
      for raster in ${RASTERS:-hardware compute}; do
        cases+=("--gi $gi --shadow $shadow --camera-path $path --raster $raster")
      done
    done
  done
done

# Renders one case with one binary into $out/WHICH/NAME.exr (its log beside it).
render() {
  local which=$1 binary=$2 scene=$3 args=$4 name=$5
  # shellcheck disable=SC2086
  "$binary" render "$scene" $args "${render_args[@]}" -q -o "$out/$which/$name" >/dev/null 2>"$out/$which/$name.log" ||
    echo "failed: $which $scene $args"
}

names=() labels=()
for scene in "${scenes[@]}"; do
  case $scene in */*) scene=$assets/$scene; [ -e "$scene" ] || { echo "skip: $scene not found"; continue; } ;; esac
  for args in "${cases[@]}"; do
    name=$(basename "${scene%.gltf}")_$(echo "$args" | tr -c 'a-z0-9' '_').exr
    names+=("$name") labels+=("$scene $args")
    for which in old new; do
      binary=$old; [ "$which" = new ] && binary=$new
      while [ "$(jobs -rp | wc -l)" -ge "$max_jobs" ]; do wait -n || true; done
      render "$which" "$binary" "$scene" "$args" "$name" &
    done
  done
done
wait
differ=0 refused=0
for i in "${!names[@]}"; do
  o=$out/old/${names[$i]} n=$out/new/${names[$i]}
  if [ ! -e "$o" ] && [ ! -e "$n" ] && cmp -s "$o.log" "$n.log"; then
    refused=$((refused + 1))  # both refused the settings with the same message (e.g. a device limit)
  elif ! cmp -s "$o" "$n"; then
    differ=$((differ + 1)) && echo "differs: ${labels[$i]}"
  fi
done
echo "${#names[@]} cases, $((${#names[@]} - differ - refused)) images identical, $refused refused by both, $differ differ"
[ "$differ" -eq 0 ]
