# Shared by the bench/*.sh scripts: the issue-14 target commands and one `bench` run per JSON.
# The caller sets bin (penumbra), assets (the assets directory) and out (the results directory).
mkdir -p "$out"
techniques="--shadow pcf --cascades 4 --shadow-res 2048 --gi lpv --lpv-res 32 --lpv-iterations 8"
full="$techniques --width 1920 --height 1080"
frames="--frames 60 --warmup 10"
sponza="$assets/sponza/glTF/Sponza.gltf --camera -9,1.7,0.3,6,4.5,0,0,1,0,70 --light directional,0.1,-1,0.2,20"
vc="$assets/VC/glTF/VC.gltf --camera 14,9,16,0,1.5,0,0,1,0,50"
run() {  # NAME ARGS...: `penumbra bench ARGS` into NAME.json and NAME.txt, its frame lines printed
  local name=$1; shift
  "$bin" bench "$@" $frames --json "$out/$name.json" > "$out/$name.txt" 2>&1 || echo "FAILED $name"
  grep -E "frame \(GPU|warm frame" "$out/$name.txt" | sed "s/^/$name: /"
}
