#!/usr/bin/env bash
# Flicker under motion: `penumbra stability` over the documented motions (cornell's default motion,
# VC and Sponza under a moving sun, Sponza with a moving camera), 8 frames at 30 fps. By default every
# shadow filter and GI mode with the path tracer's floor (`--all`); with VARIANTS the RSM defaults
# against other options without the path tracer, e.g. VARIANTS="disc:--rsm-far,disc fixed:--rsm-radii,fixed"
# (options joined by commas). One text table (and JSON) per motion and variant in OUT.
# Usage: bench/stability.sh PENUMBRA ASSETS OUT
set -uo pipefail
if [ $# -lt 3 ]; then sed -n "2,7p" "$0"; exit 2; fi
bin=$1 assets=$2 out=$3
# shellcheck source=bench/views.sh
. "$(dirname "$0")/views.sh"
mkdir -p "$out"
motions=("cornell cornell" "vc $vc_lit $vc_sun_path" "sponza $sponza $sponza_sun_path" "sponza-camera $sponza $sponza_camera_path")
if [ -z "${VARIANTS:-}" ]; then
  variants=("all:--all,--reference-max-spp,2048")
else
  variants=("default:--gi,rsm,--no-reference" )
  for v in $VARIANTS; do variants+=("${v%%:*}:--gi,rsm,--no-reference,${v#*:}"); done
fi
for m in "${motions[@]}"; do
  name=${m%% *} args=${m#* }
  for v in "${variants[@]}"; do
    label=${v%%:*} opts=${v#*:}
    # shellcheck disable=SC2086
    "$bin" stability --frames 8 ${opts//,/ } $args --json "$out/$name-$label.json" > "$out/$name-$label.txt" 2>&1 ||
      echo "failed: $name $label (see $out/$name-$label.txt)"
  done
done
tail -n +1 "$out"/*.txt
