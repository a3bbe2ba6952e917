#!/usr/bin/env bash
# The benchmark suites: each case one `penumbra bench` per binary and repeat, JSON per run, and a
# summary (the median over repeats of each run's median GPU frame, `frame_ms.median`). With two
# binaries the runs alternate on one machine and the summary gives new/old per case.
#   headline  Sponza's full frame, Sponza, VC and cornell with the defaults, hair with DSM (25k strands)
#   hair      hair with deep shadow maps and deep opacity maps, 25k and 100k strands
#   gi        RSM and LPV on cornell, VC and Sponza (PCF shadows)
#   matrix    every shadow filter on cornell, VC and hair, every GI mode on cornell and VC (SIZE for 2160p)
#   scale     LPV grid size, RSM samples, hair strands and shadow map size on one view each
#   gallery   every image of the README's gallery, by its caption's command, at full size, into OUT
# and the suites with runners of their own (the same arguments; they print their own usage):
#   flicker (bench/stability.sh), gi-variants (bench/gi_variants.sh), raster-sweep (bench/raster_sweep.sh),
#   dynamic-gi (bench/dynamic_gi.sh: OLD and NEW binaries)
# Usage: bench/run.sh SUITE ASSETS OUT PENUMBRA [OTHER_PENUMBRA]
#        bench/run.sh --table OUT   (the Markdown table of every JSON in OUT: frame and passes, with the commands)
# REPEATS (default 1; 5 for an A/B), SIZE and FRAMES (bench/views.sh) come from the environment.
set -euo pipefail
if [ "${1:-}" = --table ]; then
  exec python3 - "$2" <<'PY'
import json, pathlib, sys
runs = {p.stem: json.loads(p.read_text()) for p in sorted(pathlib.Path(sys.argv[1]).glob("*.json")) if p.name != "summary.json"}
if not runs:
    sys.exit("no run JSON in " + sys.argv[1])
first = next(iter(runs.values()))
print(f"Device: {first['device']} ({first['driver']}), {first['date']}; copy bandwidth "
      f"{first['copy_bandwidth_gbps']:.0f} GB/s; median of {first['frames']} frames after {first['warmup']} warm-up. "
      "Times in ms (median, [p5-p95]).\n")
print("| run | frame | passes (median ms; GB/s and fraction of copy bandwidth where memory-bound) |")
print("| --- | --- | --- |")
for name, r in runs.items():
    parts = [f"{p['name']} {p['median_ms']:.3f}" + (f" ({p['gbps']:.0f} GB/s, {p['fraction_of_copy_bandwidth']:.2f})"
             if "gbps" in p else "") for p in r["passes"]]
    f = r["frame_ms"]
    print(f"| {name} | {f['median']:.3f} [{f['p5']:.3f}-{f['p95']:.3f}] | {'; '.join(parts)} |")
print("\nCommands:\n")
for name, r in runs.items():
    print(f"- {name}: `{r['command']}`")
PY
fi
if [ $# -lt 4 ]; then sed -n "2,15p" "$0"; exit 2; fi
suite=$1 assets=$2 out=$3 bins=("$4" "${5:-}")
here=$(cd "$(dirname "$0")" && pwd)
case $suite in
  flicker) exec "$here/stability.sh" "$4" "$assets" "$out" ;;
  gi-variants) exec "$here/gi_variants.sh" "$4" "$assets" "$out" ;;
  raster-sweep) exec "$here/raster_sweep.sh" "$4" "$assets" "$out" ;;
  dynamic-gi) exec "$here/dynamic_gi.sh" "$4" "${5:?dynamic-gi takes OLD and NEW binaries}" "$assets" "$out" "${REPEATS:-5}" ;;
  gallery)
    # The captions' commands (scripts/check-docs.py --gallery), with this binary and ASSETS, run in OUT.
    mkdir -p "$out"
    bin=$(realpath "$4") assets=$(realpath "$assets")
    python3 "$here/../scripts/check-docs.py" --gallery | while IFS= read -r cmd; do
      cmd=${cmd//..\/shared\/assets/$assets}
      cmd=${cmd/.\/build\/penumbra/$bin}
      echo "+ $cmd"
      (cd "$out" && bash -c "$cmd") || echo "failed: $cmd"
    done
    exit 0 ;;
esac
# shellcheck source=bench/views.sh
. "$(dirname "$0")/views.sh"
mkdir -p "$out"
cases=()  # "NAME ARGS...", in the order they run
case $suite in
  headline)
    cases=("sponza-full $sponza $full_frame" "sponza-default $sponza" "vc-default $vc" "cornell-default cornell"
           "hair-25k hair --shadow pcf,dsm") ;;
  hair)
    for n in 25000 100000; do
      for t in dsm dom; do cases+=("hair-$t-$n hair --dsm-res 2048 --shadow $t --strands $n"); done
    done ;;
  gi)
    for g in rsm lpv; do
      cases+=("cornell-$g cornell --gi $g" "vc-$g $vc --gi $g" "sponza-$g $sponza --gi $g")
    done ;;
  matrix)
    for s in cornell vc hair; do
      view=$s; [ "$s" = vc ] && view=$vc
      for f in hard pcf pcss vsm msm; do cases+=("$s-shadow-$f $view --shadow $f"); done
      [ "$s" = hair ] ||
        cases+=("$s-gi-rsm-full $view --gi rsm --rsm-mode full" "$s-gi-rsm $view --gi rsm" "$s-gi-lpv $view --gi lpv")
    done
    cases+=("hair-dsm hair --shadow dsm --dsm-res 2048" "sponza-full $sponza $full_frame") ;;
  scale)
    for n in 16 32 64 128; do cases+=("lpv-res-$n $vc --gi lpv --lpv-res $n"); done
    for n in 25 100 400 1600; do cases+=("rsm-samples-$n $vc --gi rsm --rsm-mode full --rsm-samples $n"); done
    for n in 10000 50000 100000 200000; do cases+=("hair-strands-$n hair --strands $n --shadow dsm --dsm-res 2048"); done
    for n in 1024 2048 4096 8192; do cases+=("shadow-res-$n $vc --shadow pcf --shadow-res $n"); done ;;
  *) echo "bench/run.sh: unknown suite '$suite' (headline, hair, gi, matrix, scale, gallery, flicker, gi-variants, raster-sweep, dynamic-gi)" >&2; exit 2 ;;
esac
for ((r = 0; r < ${REPEATS:-1}; r++)); do
  for c in "${cases[@]}"; do
    name=${c%% *} args=${c#* }
    for i in 0 1; do
      [ -n "${bins[$i]}" ] || continue
      label=$([ $i = 0 ] && echo old || echo new); [ -n "${bins[1]}" ] || label=run
      # shellcheck disable=SC2086
      timeout 300 "${bins[$i]}" bench $args $size $frames --json "$out/${name}_${label}_$r.json" \
        > "$out/${name}_${label}_$r.txt" 2>&1 || echo "failed: ${bins[$i]} $name (see $out/${name}_${label}_$r.txt)"
    done
  done
done
python3 - "$out" <<'PY'
import json, pathlib, statistics, sys
out = pathlib.Path(sys.argv[1])
runs = {}
for f in sorted(out.glob("*_*_*.json")):
    name, binary, _ = f.stem.rsplit("_", 2)
    runs.setdefault(name, {}).setdefault(binary, []).append(json.loads(f.read_text())["frame_ms"]["median"])
summary = {}
for name, by in runs.items():
    row = {f"{b}_ms": statistics.median(v) for b, v in by.items()}
    row["runs"] = max(len(v) for v in by.values())
    if "old_ms" in row and "new_ms" in row:
        row["ratio"] = row["new_ms"] / row["old_ms"]
    summary[name] = row
    print(f"{name:<20} " + "  ".join(f"{k} {v:.3f}" if isinstance(v, float) else f"{k} {v}" for k, v in row.items()))
(out / "summary.json").write_text(json.dumps(summary, indent=2) + "\n")
PY
