#!/usr/bin/env bash
# 2026-11-26 (session 25), second run: the binary search reading packed depth keys, the resolve's
# shorter sort array (PENUMBRA_DSM_LONG=1: the general one), and the RSM gather's lanes per receiver
# taking runs of consecutive samples (PENUMBRA_RSM_LANES_LIST / _LOW).
# (PENUMBRA_DSM_LONG and PENUMBRA_RSM_LANES_* were read by an uncommitted
# experiment build; the committed code has neither.)
# Usage (device): bench/hair_v11.sh PENUMBRA ASSETS_DIR OUT_DIR
set -euo pipefail
bin=$1 assets=$2 out=$3
. "$(dirname "$0")/lib.sh"
hair="hair --dsm-res 2048 --width 1920 --height 1080 --shadow dsm"
for n in 25000 100000; do
  run hair${n}_search $hair --strands $n
  PENUMBRA_DSM_LONG=1 run hair${n}_search_long $hair --strands $n
done
PENUMBRA_OIT_EXP=1 run hair25000_nodsm $hair --strands 25000
for s in cornell vc sponza; do
  case $s in cornell) args=cornell;; vc) args=$vc;; sponza) args=$sponza;; esac
  for l in 1 4 8; do PENUMBRA_RSM_LANES_LIST=$l run ${s}_rsm_list$l $args --width 1920 --height 1080 --gi rsm; done
  for l in 2 4; do PENUMBRA_RSM_LANES_LOW=$l run ${s}_rsm_low$l $args --width 1920 --height 1080 --gi rsm; done
done
summarize
