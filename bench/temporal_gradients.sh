#!/usr/bin/env bash
# A GI technique's temporal gradients (--rsm-lag-tolerance, --lpv-lag-tolerance) on one machine, sun only (--sky none); the
# technique is GI=rsm (the default) or GI=lpv in the environment:
# - lag: Sponza's nave under the strip's moving sun (0.55 degrees a frame), 320x180 indirect light;
#   frames 36 and 71 of the sequence against the converged still image of that instant (64 frames
#   within 6.4 ms of scene time), relative L1;
# - flicker: `stability` RMS indirect flicker (128x96, 8 frames after 32) of the default RSM on
#   cornell's spot sweep, VC and Sponza under a fast sun and Sponza under a moving camera (the GI
#   technique's own flicker, temporal GI on);
# - cost: bench of the default frames at 1920x1080 (Sponza still and under the moving sun, cornell,
#   VC), OLD and NEW interleaved, and NEW's per-pass median of the gradient pass ("$GI.gradient").
# Usage: [GI=rsm|lpv] bench/temporal_gradients.sh OLD NEW ASSETS OUTDIR ["TOLERANCES"] [REPEATS]
set -uo pipefail
old=$1 new=$2 assets=$3 out=$4 tolerances=${5:-"1 2 3 1000"} repeats=${6:-3} gi=${GI:-rsm}
mkdir -p "$out"
# shellcheck source=bench/views.sh
. "$(dirname "$0")/views.sh"
tmp=$(mktemp -d)
strip="$assets/sponza/glTF/Sponza.gltf --camera -9,1.7,0.3,6,4.5,0,0,1,0,70 --light directional,0.1,-1,0.2,20"
strip="$strip --sun-path 63.4,77.4,98.4,59.9,2.4 --width 320 --height 180 --sky none --aov indirect --gi $gi"
metric() { "$new" compare "$1" "$2" --json | python3 -c "import json,sys; print(json.load(sys.stdin)['rel_l1'])"; }
{
  echo "{\"command\": \"GI=$gi bench/temporal_gradients.sh $*\", \"gi\": \"$gi\", \"lag\": {"
  for f in 36 71; do
    # shellcheck disable=SC2086
    "$new" render $strip --time "$(python3 -c "print($f / 30)")" --sequence 64 --fps 10000 -o "$tmp/still_${f}_%04d.exr" >/dev/null 2>&1
  done
  first=1
  for tol in $tolerances; do
    # shellcheck disable=SC2086
    "$new" render $strip "--$gi-lag-tolerance" "$tol" --sequence 72 -o "$tmp/seq_%04d.exr" >/dev/null 2>&1
    [ $first = 1 ] || echo ','
    first=0
    echo "\"$tol\": {\"frame36\": $(metric "$tmp/seq_0036.exr" "$tmp/still_36_0063.exr"), \"frame71\": $(metric "$tmp/seq_0071.exr" "$tmp/still_71_0063.exr")}"
  done
  echo '}, "flicker": {'
  stab="stability --frames 8 --warmup 32 --no-reference --width 128 --height 96 --sky none --gi $gi"
  first=1
  for m in "cornell|cornell" "vc-sun|$vc_lit $vc_sun_path" "sponza-sun|$sponza $sponza_sun_path" "sponza-camera|$sponza $sponza_camera_path"; do
    for tol in $tolerances; do
      # shellcheck disable=SC2086
      "$new" $stab ${m#*|} "--$gi-lag-tolerance" "$tol" --json "$tmp/st.json" >/dev/null 2>&1
      [ $first = 1 ] || echo ','
      first=0
      echo "\"${m%%|*} $tol\": $(python3 -c "import json; print(json.load(open('$tmp/st.json'))['techniques'][0]['indirect_flicker_rms'])")"
    done
  done
  echo '}}'
} > "$tmp/figures.json"
hd="--width 1920 --height 1080 --frames 60 --warmup 10 --sky none --gi $gi"
for ((r = 0; r < repeats; r++)); do
  for c in "sponza|$sponza $hd" "sponza-moving-sun|$sponza $hd --sun-path 63.4,77.4,98.4,59.9,2.4" "cornell|cornell $hd" \
           "vc|$vc $hd"; do
    for bin in old new; do  # interleaved
      b=$old; [ $bin = new ] && b=$new
      # shellcheck disable=SC2086
      "$b" bench ${c#*|} --json "$tmp/c.json" >/dev/null 2>&1 || continue
      python3 -c "import json
d = json.load(open('$tmp/c.json'))
print('${c%%|*} $bin', d['frame_ms']['median'])
if '$bin' == 'new':  # the gradient pass's own time (the frame's passes timed one by one)
    print(*('${c%%|*} ' + p['name'] + ' ' + str(p['median_ms']) for p in d['passes'] if p['name'] == '$gi.gradient'))" \
        >> "$tmp/cost.txt"
    done
  done
done
python3 - "$tmp" "$out" <<'PY'
import json, pathlib, statistics, sys
tmp, out = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
d = json.loads((tmp / "figures.json").read_text())
runs = {}
for line in (tmp / "cost.txt").read_text().split("\n"):
    if line:
        name, binary, ms = line.split()
        runs.setdefault(name, {}).setdefault(binary, []).append(float(ms))
d["cost_ms"] = {n: {b: {"runs": v, "median": statistics.median(v)} for b, v in by.items()} for n, by in runs.items()}
(out / "temporal_gradients.json").write_text(json.dumps(d, indent=2) + "\n")
PY

rm -rf "$tmp"
python3 -m json.tool "$out/temporal_gradients.json"
