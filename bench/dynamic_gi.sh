#!/usr/bin/env bash
# Dynamic GI on one machine: what the temporal GI costs and what it buys.
# - cost: bench of the default frames (Sponza at 1920x1080 and 3840x2160, VC, cornell; Sponza and VC
#   also under a moving sun), OLD and NEW binaries interleaved REPEATS times; median of run medians;
# - flicker: `stability` (128x96, 8 measured frames after 32 still ones) of the default RSM and LPV on
#   cornell's spot sweep, VC and Sponza under a moving sun and Sponza under a moving camera, with the
#   temporal GI on (the default) and off;
# - response: `stability --change` (320x180, 64 frames to settle): cornell's light off and on, the sun
#   of VC and Sponza turning 20 degrees;
# - noise: the first frame of a still view against the 64th (`render --sequence`, 320x180, indirect).
# Usage: bench/dynamic_gi.sh OLD NEW ASSETS OUTDIR [REPEATS] [PARTS]   (PARTS: any of cost flicker
# response noise, quoted; default all)
set -euo pipefail
old=$1 new=$2 assets=$3 out=$4 repeats=${5:-5} parts=${6:-"cost flicker response noise"}
part() { [[ " $parts " == *" $1 "* ]]; }
mkdir -p "$out"
# shellcheck source=bench/views.sh
. "$(dirname "$0")/views.sh"
vc=$vc_lit
hd="--width 1920 --height 1080 --frames 60 --warmup 10"
declare -A cases=(
  [sponza-default]="$sponza $hd"
  [sponza-default-4k]="$sponza --width 3840 --height 2160 --frames 30 --warmup 10"
  [sponza-moving-sun]="$sponza $hd --sun-path 63.4,77.4,98.4,59.9,2.4"
  [vc-default]="$vc $hd"
  [vc-moving-sun]="$vc $hd --sun-path 53.1,63.4,88.1,45.9,2.4"
  [cornell-default]="cornell $hd"
)
part cost && for ((r = 0; r < repeats; r++)); do
  for name in "${!cases[@]}"; do
    for bin in old new; do
      b=$old; [ $bin = new ] && b=$new
      # shellcheck disable=SC2086
      timeout 120 "$b" bench ${cases[$name]} --json "$out/cost_${name}_${bin}_$r.json" >/dev/null ||
        echo "failed: $bin $name run $r"
    done
  done
done
part cost && python3 - "$out" <<'PY'
import json, pathlib, statistics, sys
out = pathlib.Path(sys.argv[1])
runs = {}
for f in out.glob("cost_*_*_*.json"):
    name, binary, _ = f.stem[len("cost_"):].rsplit("_", 2)
    runs.setdefault(name, {}).setdefault(binary, []).append(json.loads(f.read_text())["frame_ms"]["median"])
summary = {}
for name, by in sorted(runs.items()):
    old, new = statistics.median(by["old"]), statistics.median(by["new"])
    summary[name] = {"old_ms": old, "new_ms": new, "ratio": new / old, "runs": len(by["new"])}
    print(f"{name:<18} old {old:7.3f} ms  new {new:7.3f} ms  new/old {new / old:6.3f}  ({len(by['new'])} runs)")
    for binary in ("old", "new"):  # the costliest passes of the first run
        passes = json.loads((out / f"cost_{name}_{binary}_0.json").read_text())["passes"]
        top = sorted(passes, key=lambda p: -p["median_ms"])[:8]
        summary[name][f"{binary}_passes_ms"] = {p["name"]: p["median_ms"] for p in passes}
        print(f"    {binary}: " + ", ".join(f"{p['name']} {p['median_ms']:.3f}" for p in top))
(out / "cost_summary.json").write_text(json.dumps(summary, indent=2) + "\n")
PY

stab="stability --frames 8 --warmup 32 --no-reference --width 128 --height 96"
declare -A motions=(
  [cornell]="cornell"
  [vc-sun]="$vc $vc_sun_path"
  [sponza-sun]="$sponza $sponza_sun_path"
  [sponza-camera]="$sponza $sponza_camera_path"
)
part flicker && for name in "${!motions[@]}"; do
  for gi in rsm lpv; do
    for temporal in on off; do
      # shellcheck disable=SC2086
      "$new" $stab ${motions[$name]} --gi $gi --gi-temporal $temporal \
        --json "$out/flicker_${name}_${gi}_temporal-${temporal}.json" >/dev/null || echo "failed: flicker $name $gi $temporal"
    done
  done
done
part flicker && python3 - "$out" <<'PY'
import json, pathlib, sys
out = pathlib.Path(sys.argv[1])
for f in sorted(out.glob("flicker_*.json")):
    t = json.loads(f.read_text())["techniques"][0]
    print(f"{f.stem:<44} indirect RMS flicker {t['indirect_flicker_rms']:.4f}")
PY

resp="stability --settle 64 --frames 8 --width 320 --height 180"
declare -A changes=(
  [cornell-off]="cornell --change off"
  [cornell-on]="cornell --change on"
  [vc-sun20]="$vc --change sun:20"
  [sponza-sun20]="$sponza --change sun:20"
)
part response && for name in "${!changes[@]}"; do
  for gi in rsm lpv; do
    # shellcheck disable=SC2086
    "$new" $resp ${changes[$name]} --gi $gi --json "$out/response_${name}_${gi}.json" >/dev/null ||
      echo "failed: response $name $gi"
  done
done
part response && python3 - "$out" <<'PY'
import json, pathlib, sys
out = pathlib.Path(sys.argv[1])
for f in sorted(out.glob("response_*.json")):
    t = json.loads(f.read_text())["techniques"][0]
    r = {x["k"]: x for x in t["r"]}
    print(f"{f.stem:<32} pixels {t['pixels_changed']:6d}  r_1 {r[1]['median']:.3f}  r_2 {r[2]['median']:.3f} "
          f"(p05 {r[2]['p05']:.3f})  r_8 {r[8]['median']:.3f}")
PY

declare -A views=([cornell]="cornell" [vc]="$vc" [sponza]="$sponza")
part noise && for name in "${!views[@]}"; do
  for gi in rsm lpv; do
    dir="$out/noise_${name}_${gi}"
    mkdir -p "$dir"
    # shellcheck disable=SC2086
    # --fps 10000: 64 frames within 6.4 ms of scene time, a still view even where the scene moves.
    "$new" render ${views[$name]} --gi $gi --aov indirect --width 320 --height 180 --sequence 64 --fps 10000 \
      -o "$dir/f_%04d.exr" >/dev/null || echo "failed: noise $name $gi"
    first=$(ls "$dir"/f_*.exr | head -1) last=$(ls "$dir"/f_*.exr | tail -1)
    "$new" compare "$first" "$last" --json > "$out/noise_${name}_${gi}.json" || echo "failed: compare $name $gi"
    rm -rf "$dir"
    python3 -c "import json,sys; m=json.load(open(sys.argv[1])); print(f\"noise {sys.argv[2]:<12} first frame vs 64th: rel L1 {m.get('rel_l1', m)}\")" \
      "$out/noise_${name}_${gi}.json" "${name}-${gi}"
  done
done
