#!/usr/bin/env bash
# Issue 13, the flux-drawn far samples (--rsm-far flux): the RSM gather's cost at 1080p before and after
# on one machine. BINS: NAME=PATH[:OPTIONS] ... (options joined by commas), interleaved twice; cornell,
# VC and Sponza with --gi rsm --raster auto, cold frames; then the GI suite of the first binary.
# Usage (device): BINS="old=A new=B disc=B:--rsm-far,disc" bench/rsm_far_ab.sh ASSETS_DIR OUT_DIR
set -euo pipefail
assets=$1 out=$2
. "$(dirname "$0")/lib.sh"
for round in 1 2; do
  for entry in $BINS; do
    name=${entry%%=*} spec=${entry#*=} bin=${spec%%:*} opts=
    [[ $spec == *:* ]] && opts=${spec#*:} && opts=${opts//,/ }
    run cornell-$name-$round cornell --width 1920 --height 1080 --gi rsm --raster auto $opts
    run vc-$name-$round $vc --width 1920 --height 1080 --gi rsm --raster auto $opts
    run sponza-$name-$round $sponza --width 1920 --height 1080 --gi rsm --raster auto $opts
  done
done
# The gather's passes (all rsm.* after the RSM's resolve), summed per run.
for f in "$out"/*.json; do python3 -c "
import json, sys; d = json.load(open(sys.argv[1]))
g = sum(p['median_ms'] for p in d['passes'] if p['name'].startswith('rsm.') and p['name'] != 'rsm.resolve')
print(sys.argv[1].split('/')[-1][:-5], 'frame %.3f' % d['frame_ms']['median'], 'gather %.3f' % g,
      ' '.join(f\"{p['name']}={p['median_ms']:.3f}\" for p in d['passes'] if p['name'].startswith('rsm.')))" "$f"
done | tee "$out/gather.txt"
