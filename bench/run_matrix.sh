#!/usr/bin/env bash
# The standard benchmark matrix, one process per configuration, one JSON each (bench/README.md).
# Usage: bench/run_matrix.sh PENUMBRA_BINARY VC_GLTF OUT_DIR [quick]
# On the GPU machine: . .device/env.sh; bench/run_matrix.sh .device/penumbra .device/assets/VC/glTF/VC.gltf $OUT/bench
set -uo pipefail
P=$1; VC=$2; OUT=$3; QUICK=${4:-}
mkdir -p "$OUT"
FRAMES=100; WARM=10
[ -n "$QUICK" ] && FRAMES=3 && WARM=1
VCCAM="--camera 14,9,16,0,1.5,0,0,1,0,50"
fail=0
run() {  # name, args...
  local name=$1; shift
  echo "== $name: $*"
  if ! "$P" bench "$@" --frames $FRAMES --warmup $WARM --json "$OUT/$name.json" > "$OUT/$name.txt" 2> "$OUT/$name.err"; then
    echo "   FAILED: $(tail -1 "$OUT/$name.err")"; fail=1
  fi
}
scene_args() {  # scene key -> scene arguments
  case $1 in cornell) echo "cornell";; vc) echo "$VC $VCCAM";; hair) echo "hair";; esac
}
for res in 1920x1080 3840x2160; do
  W=${res%x*}; H=${res#*x}
  for s in cornell vc hair; do
    for shadow in hard pcf pcss vsm msm; do
      run "${s}_${res}_shadow-${shadow}" $(scene_args $s) --width $W --height $H --shadow $shadow
    done
  done
  for s in cornell vc; do
    run "${s}_${res}_gi-rsm-full" $(scene_args $s) --width $W --height $H --gi rsm --rsm-mode full
    run "${s}_${res}_gi-rsm-interp" $(scene_args $s) --width $W --height $H --gi rsm
    run "${s}_${res}_gi-lpv" $(scene_args $s) --width $W --height $H --gi lpv
  done
  run "hair_${res}_dsm" hair --width $W --height $H --shadow dsm --dsm-res 2048
done
# Scaling (1920x1080).
for n in 16 32 64 128; do run "scale_lpv-${n}" $VC $VCCAM --gi lpv --lpv-res $n --width 1920 --height 1080; done
for n in 25 100 400 1600; do run "scale_rsm-samples-${n}" $VC $VCCAM --gi rsm --rsm-mode full --rsm-samples $n --width 1920 --height 1080; done
for n in 10000 50000 100000 200000; do run "scale_dsm-strands-${n}" hair --strands $n --shadow dsm --dsm-res 2048 --width 1920 --height 1080; done
for n in 1024 2048 4096 8192; do run "scale_shadow-res-${n}" $VC $VCCAM --shadow pcf --shadow-res $n --width 1920 --height 1080; done
# The full frame of the issue: CSM 4 x 2048^2 PCF + LPV 32^3 x 8 with occlusion + deferred.
run "vc_1920x1080_full-frame" $VC $VCCAM --width 1920 --height 1080 --shadow pcf --gi lpv
exit $fail
