#!/usr/bin/env python3
"""Markdown tables from the JSON files of bench/run_matrix.sh: python3 bench/make_table.py DIR > DIR/table.md"""
import json, pathlib, sys

def load(d):
    return {p.stem: json.loads(p.read_text()) for p in sorted(pathlib.Path(d).glob("*.json"))}

def main(d):
    runs = load(d)
    if not runs:
        sys.exit("no JSON files in " + d)
    first = next(iter(runs.values()))
    print(f"Device: {first['device']} ({first['driver']}), {first['date']}; "
          f"copy bandwidth {first['copy_bandwidth_gbps']:.0f} GB/s; median of {first['frames']} frames after "
          f"{first['warmup']} warm-up. Times in ms (median, [p5-p95]).\n")
    print("| configuration | frame | passes (median ms; GB/s and fraction of copy bandwidth where memory-bound) |")
    print("| --- | --- | --- |")
    for name, r in runs.items():
        parts = []
        for p in r["passes"]:
            s = f"{p['name']} {p['median_ms']:.3f}"
            if "gbps" in p:
                s += f" ({p['gbps']:.0f} GB/s, {p['fraction_of_copy_bandwidth']:.2f})"
            parts.append(s)
        f = r["frame_ms"]
        print(f"| {name} | {f['median']:.3f} [{f['p5']:.3f}-{f['p95']:.3f}] | {'; '.join(parts)} |")
    print("\nCommands:\n")
    for name, r in runs.items():
        print(f"- {name}: `{r['command']}`")

if __name__ == "__main__":
    main(sys.argv[1])
