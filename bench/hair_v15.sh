#!/usr/bin/env bash
# 2026-11-26 (session 25): the camera translucency composite split into oit.sort (per pixel),
# oit.shade (one thread per kept layer) and oit.blend (per pixel).
# Usage (device): bench/hair_v15.sh PENUMBRA ASSETS_DIR OUT_DIR
set -euo pipefail
bin=$1 assets=$2 out=$3
. "$(dirname "$0")/lib.sh"
for n in 25000 100000; do
  run hair_1920x1080_dsm-$n $hair --shadow dsm --strands $n
  run hair_1920x1080_dom-$n $hair --shadow dom --strands $n
done
summarize
