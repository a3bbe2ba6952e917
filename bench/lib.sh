# Shared by the bench/*.sh scripts: the issue-14 target commands and one `bench` run per JSON.
# The caller sets bin (penumbra), assets (the assets directory) and out (the results directory).
mkdir -p "$out"
techniques="--shadow pcf --cascades 4 --shadow-res 2048 --gi lpv --lpv-res 32 --lpv-iterations 8"
full="$techniques --width 1920 --height 1080"
frames="--frames 60 --warmup 10"
sponza="$assets/sponza/glTF/Sponza.gltf --camera -9,1.7,0.3,6,4.5,0,0,1,0,70 --light directional,0.1,-1,0.2,20"
vc="$assets/VC/glTF/VC.gltf --camera 14,9,16,0,1.5,0,0,1,0,50"
hair="hair --dsm-res 2048 --width 1920 --height 1080"  # issue 15's frame, with --shadow and --strands
run() {  # NAME ARGS...: `penumbra bench ARGS` into NAME.json and NAME.txt, its frame lines printed
  local name=$1; shift
  "$bin" bench "$@" $frames --json "$out/$name.json" > "$out/$name.txt" 2>&1 || echo "FAILED $name"
  grep -E "frame \(GPU|warm frame" "$out/$name.txt" | sed "s/^/$name: /"
}
summarize() {  # one line per JSON of $out: name, median frame ms, the passes above 0.05 ms
  for f in "$out"/*.json; do python3 -c "
import json, sys; d = json.load(open(sys.argv[1]))
print(sys.argv[1].split('/')[-1], round(d['frame_ms']['median'], 2),
      ' '.join(f\"{p['name']}={p['median_ms']:.2f}\" for p in d['passes'] if p['median_ms'] > 0.05))" "$f"; done
}
