#!/usr/bin/env bash
# 2026-11-26 (session 28): the frame graph's groups (independent passes run together, one barrier
# between dependent groups) against a base binary, on the same warm machine one after the other:
# issue 15's hair frames, and cornell, VC and Sponza with GI. The new binary runs each frame with its
# groups (the default) and with --overlap off (the passes one after another). Its `frame_ms` comes
# from frames timed as a whole, `frame_ms_pass_scopes` from the same frames with a scope per pass
# (which run the passes in order: the base binary's only measure). Wall clock per frame (two frames
# in flight) is printed beside the GPU's frame time.
# Usage (device): bench/overlap_ab.sh BASE NEW ASSETS_DIR OUT_DIR
set -euo pipefail
base=$1 new=$2 assets=$3 out=$4
bin=$new
. "$(dirname "$0")/lib.sh"
three() {  # NAME ARGS...: base, then the new binary with its groups and without
  local name=$1; shift
  bin=$base run base-$name "$@"
  bin=$new run $name "$@"
  bin=$new run serial-$name "$@" --overlap off
  for v in base- "" serial-; do grep -E "pass scopes|wall clock" "$out/$v$name.txt" | sed "s/^/$v$name: /"; done
}
for n in 25000 100000; do three hair_1920x1080_dsm-$n $hair --shadow dsm --strands $n; done
for n in 25000 100000; do three hair_1920x1080_dom-$n $hair --shadow dom --strands $n; done
three cornell_1920x1080_rsm cornell --width 1920 --height 1080 --gi rsm
three vc_1920x1080_rsm $vc --width 1920 --height 1080 --gi rsm
three sponza_1920x1080_full $sponza $full
summarize
