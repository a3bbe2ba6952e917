#!/usr/bin/env bash
# --raster compute, hardware (and auto) over --shadow-res 512 .. 4096 (8192 at a few points), five
# scenes and three light kinds: the sweep behind `--raster auto` (docs/techniques/shadows.md). 1920x1080, --gi none,
# PCF; the sun with 4 cascades. One `bench` per point into OUTDIR/NAME.json and NAME.txt; a point that
# runs past its time limit is recorded as TIMEOUT, one the device refuses (penumbra: error) as REFUSED.
# Usage: bench/raster_sweep.sh BIN ASSETS OUTDIR [MODES] [SCENES] [SIZES] [LIGHTS]
#        bench/raster_sweep.sh --table OUTDIR...   (one JSON of every point, to stdout)
#        bench/raster_sweep.sh --markdown SWEEP.json   (the table: compute and hardware side by side, auto)
set -uo pipefail
if [ "${1:-}" = --markdown ]; then
  exec python3 - "$2" <<'PY'
import json, sys
points = {(p["scene"], p["light"], p["shadow_res"], p["mode"]): p for p in json.load(open(sys.argv[1]))}
def ms(key):
    p = points.get(key)
    return None if p is None else p["frame_ms"] if p["status"] == "ok" else p["status"]
print("| scene | light | `--shadow-res` | compute ms | hardware ms | hardware / compute | auto picks | auto ms (measured) | auto within bound |")
print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
for key in sorted({k[:3] for k in points}, key=lambda k: (k[0], ["sun", "spot", "point"].index(k[1]), k[2])):
    c, h, a = ms(key + ("compute",)), ms(key + ("hardware",)), ms(key + ("auto",))
    if not isinstance(c, float) or not isinstance(h, float):
        print(f"| {key[0]} | {key[1]} | {key[2]} | {c} | {h} | | | | |")
        continue
    # auto's rule on NVIDIA H100/H200: compute at every size it accepts (up to 16384)
    pick, picked = ("compute", c) if key[2] <= 16384 else ("hardware", h)
    bound = max(1.2 * min(c, h), min(c, h) + 0.05)
    print(f"| {key[0]} | {key[1]} | {key[2]} | {c:.3f} | {h:.3f} | {h / c:.2f} | {pick} | "
          f"{'' if a is None else f'{a:.3f}'} | {'yes' if picked <= bound else 'NO'} |")
PY
fi
if [ "${1:-}" = --table ]; then
  shift
  exec python3 - "$@" <<'PY'
import glob, json, os, sys
points = {}
for d in sys.argv[1:]:
    for txt in sorted(glob.glob(os.path.join(d, "*.txt"))):
        name = os.path.basename(txt)[:-4]
        scene, light, res, mode = name.split("_")
        p = {"scene": scene, "light": light, "shadow_res": int(res), "mode": mode}
        text = open(txt).read()
        js = txt[:-4] + ".json"
        if "TIMEOUT" in text: p["status"] = "timeout"
        elif "penumbra: error" in text:
            p["status"] = "refused"
            p["message"] = next(l for l in text.splitlines() if "penumbra: error" in l)
        elif os.path.exists(js):
            j = json.load(open(js))
            p.update(status="ok", device=j["device"], command=j["command"], frame_ms=j["frame_ms"]["median"],
                     raster=j["settings"].get("raster"), triangles=j["scene"]["triangles"],
                     shadow_passes={q["name"]: q["median_ms"] for q in j["passes"] if q["name"].startswith("shadow")})
        else: p["status"] = "failed"
        points[name] = p  # a later directory's run of the same point replaces an earlier one
print(json.dumps(sorted(points.values(), key=lambda p: (p["scene"], p["light"], p["shadow_res"], p["mode"])), indent=1))
PY
fi
if [ $# -lt 3 ]; then sed -n "2,8p" "$0"; exit 2; fi
bin=$1 assets=$2 out=$3
# shellcheck source=bench/views.sh
. "$(dirname "$0")/views.sh"
modes=${4:-compute hardware}
scenes=${5:-terrain cornell vc sponza hair}
sizes=${6:-512 1024 2048 3072 4096}
kinds=${7:-sun spot point}
mkdir -p "$out"
common="$size --gi none --shadow pcf --cascades 4 ${FRAMES:---frames 20 --warmup 5}"
declare -A scene sun spot point
scene[terrain]="terrain"
sun[terrain]="directional,0.5,-0.45,0.35,4"
spot[terrain]="spot,-14,22,12,16,-22,-16,800,50,40"
point[terrain]="point,0,4,0,400"
scene[cornell]="cornell"
sun[cornell]="directional,0.1,-1,0.2,3"
spot[cornell]="spot,0,1.9,0,0,-1,0,6,65,50"
point[cornell]="point,0,1.5,0,3"
scene[vc]="$vc"
sun[vc]="directional,0.1,-1,0.2,20"
spot[vc]="spot,12,18,10,-0.5,-0.7,-0.45,2000,45,35"
point[vc]="point,0,6,0,500"
scene[sponza]="$sponza"  # --light below replaces the view's sun
sun[sponza]="directional,0.1,-1,0.2,20"
spot[sponza]="spot,0,11,0,0,-1,0,800,60,45"
point[sponza]="point,0,5,0,300"
scene[hair]="hair --dsm-res 2048"
sun[hair]="directional,0.3,-1,0.2,3"
spot[hair]="spot,-0.9,1.3,-0.2,0.9,-1,0.2,6,28,20"
point[hair]="point,-0.6,1.1,0.3,3"

point_run() {  # NAME LIMIT_S ARGS...
  local name=$1 limit=$2; shift 2
  # shellcheck disable=SC2068
  timeout "$limit" "$bin" bench $@ --json "$out/$name.json" >"$out/$name.txt" 2>&1
  local rc=$?
  if [ $rc -eq 124 ]; then echo "$name TIMEOUT (${limit}s)"; echo TIMEOUT >>"$out/$name.txt"
  elif grep -q "penumbra: error" "$out/$name.txt"; then echo "$name REFUSED: $(grep -m1 'penumbra: error' "$out/$name.txt")"
  elif [ $rc -ne 0 ]; then echo "$name FAILED rc=$rc"
  else echo "$name $(grep -E 'frame \(GPU' "$out/$name.txt")"; fi
}

light_of() {  # KIND SCENE: the --light value
  local -n table=$1
  echo "${table[$2]}"
}

for s in $scenes; do
  for kind in $kinds; do
    for res in $sizes; do
      limit=25; [ "$res" -ge 8192 ] && limit=60
      for mode in $modes; do
        point_run "${s}_${kind}_${res}_${mode}" $limit "${scene[$s]} --light $(light_of "$kind" "$s") --shadow-res $res --raster $mode $common"
      done
    done
  done
done
