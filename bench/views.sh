# The views every bench script measures, written once (sourced; the caller sets `assets`, the folder
# holding sponza/ and VC/: the glTF sample models and Crytek Sponza, ../shared/assets in a checkout
# of this repository).
# shellcheck shell=bash disable=SC2034
# Sponza's nave and VC's overview are penumbra's named views (`--view`; the nave's carries its sun).
sponza="$assets/sponza/glTF/Sponza.gltf --view nave"
vc="$assets/VC/glTF/VC.gltf --view overview"
# The moving lights and camera of the flicker measurements (bench/stability.sh).
vc_lit="$vc --light directional,0.3,-1,0.4,6"
sponza_sun_path="--sun-path 63.4,77.4,75.4,71.4,0.26667"
vc_sun_path="--sun-path 53.1,63.4,65.1,57.4,0.26667"
sponza_camera_path="--camera-keys 0,-9,1.7,0.3,6,4.5,0;0.26667,-8.2,1.7,0.5,6.8,4.5,0.2"
# Sponza's full frame: PCF with 4 cascades of 2048^2 and a 32^3 LPV.
full_frame="--shadow pcf --cascades 4 --shadow-res 2048 --gi lpv --lpv-res 32 --lpv-iterations 8"
# Size and frame count of a timed run; FRAMES and SIZE override them (e.g. a quick check on lavapipe).
size=${SIZE:-"--width 1920 --height 1080"}
frames=${FRAMES:-"--frames 60 --warmup 10"}
