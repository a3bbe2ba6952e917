#!/usr/bin/env bash
# The headline frames measured with two penumbra binaries, interleaved on one machine: Sponza's full
# frame (PCF, 4 x 2048^2 cascades, LPV 32^3), Sponza and VC with the defaults, cornell, and hair
# (25k strands, PCF with deep shadow maps), all at 1920x1080. Each case runs REPEATS times per binary,
# old and new alternating; the summary is the median over runs of each run's median cold frame.
# Usage: bench/headline_ab.sh OLD NEW ASSETS OUTDIR [REPEATS]   (writes OUTDIR/*.json and summary.json)
set -euo pipefail
old=$1 new=$2 assets=$3 out=$4 repeats=${5:-5}
mkdir -p "$out"
size="--width 1920 --height 1080 --frames 60 --warmup 10"
sponza="$assets/sponza/glTF/Sponza.gltf --camera -9,1.7,0.3,6,4.5,0,0,1,0,70 --light directional,0.1,-1,0.2,20"
vc="$assets/VC/glTF/VC.gltf --camera 14,9,16,0,1.5,0,0,1,0,50"
declare -A cases=(
  [sponza-full]="$sponza --shadow pcf --cascades 4 --shadow-res 2048 --gi lpv --lpv-res 32 --lpv-iterations 8"
  [sponza-default]="$sponza"
  [vc-default]="$vc"
  [cornell-default]="cornell"
  [hair-25k]="hair --shadow pcf,dsm"
)
for ((r = 0; r < repeats; r++)); do
  for name in "${!cases[@]}"; do
    for bin in old new; do
      b=$old; [ $bin = new ] && b=$new
      # shellcheck disable=SC2086
      timeout 120 "$b" bench ${cases[$name]} $size --json "$out/${name}_${bin}_$r.json" >/dev/null ||
        echo "failed: $bin $name run $r"
    done
  done
done
python3 - "$out" <<'PY'
import json, pathlib, statistics, sys
out = pathlib.Path(sys.argv[1])
runs = {}
for f in out.glob("*_*_*.json"):
    name, binary, _ = f.stem.rsplit("_", 2)
    runs.setdefault(name, {}).setdefault(binary, []).append(json.loads(f.read_text())["frame_ms"]["median"])
summary = {}
for name, by in sorted(runs.items()):
    old, new = statistics.median(by["old"]), statistics.median(by["new"])
    summary[name] = {"old_ms": old, "new_ms": new, "ratio": new / old, "runs": len(by["new"])}
    print(f"{name:<16} old {old:7.3f} ms  new {new:7.3f} ms  new/old {new / old:6.3f}  ({len(by['new'])} runs)")
(out / "summary.json").write_text(json.dumps(summary, indent=2) + "\n")
PY
