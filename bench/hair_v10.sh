#!/usr/bin/env bash
# 2026-11-26 (session 25): issue 15's hair frames with the DSM lookup by binary search against the
# link walk, the composite's parts switched off one at a time (PENUMBRA_OIT_EXP, an uncommitted
# experiment build), and the RSM gather's lanes per receiver (PENUMBRA_RSM_LANES_*).
# (PENUMBRA_OIT_EXP and PENUMBRA_RSM_LANES_* were read by an uncommitted
# experiment build; the committed code has neither.)
# Usage (device): bench/hair_v10.sh PENUMBRA ASSETS_DIR OUT_DIR
set -euo pipefail
bin=$1 assets=$2 out=$3
. "$(dirname "$0")/lib.sh"
hair="hair --dsm-res 2048 --width 1920 --height 1080 --shadow dsm"
run hair25_links $hair --strands 25000 --dsm-lookup links
run hair25_search $hair --strands 25000 --dsm-lookup search
for e in 1 2 4; do PENUMBRA_OIT_EXP=$e run hair25_search_exp$e $hair --strands 25000; done
PENUMBRA_RSM_LANES_LIST=1 run hair25_search_list1 $hair --strands 25000
run hair100_links $hair --strands 100000 --dsm-lookup links
run hair100_search $hair --strands 100000 --dsm-lookup search
run hair25_dom hair --dsm-res 2048 --width 1920 --height 1080 --shadow dom --strands 25000
for l in 1 4 8; do PENUMBRA_RSM_LANES_LIST=$l run cornell_rsm_list$l cornell --width 1920 --height 1080 --gi rsm; done
for l in 2 4; do PENUMBRA_RSM_LANES_LOW=$l run cornell_rsm_low$l cornell --width 1920 --height 1080 --gi rsm; done
for l in 1 8; do PENUMBRA_RSM_LANES_LIST=$l run vc_rsm_list$l $vc --width 1920 --height 1080 --gi rsm; done
PENUMBRA_RSM_LANES_LOW=2 run vc_rsm_low2 $vc --width 1920 --height 1080 --gi rsm
for l in 1 8; do PENUMBRA_RSM_LANES_LIST=$l run sponza_rsm_list$l $sponza --width 1920 --height 1080 --gi rsm; done
summarize
