// The options that define one frame (scene, camera, lights, time and motion; the pipeline's settings
// are RenderSettings), each parsed once by its option row into a typed value, and the preparation of
// the scene, camera and motion they describe. Shared by the command line and the viewer; no command
// line parser here (app/frame_cli.h registers the rows on one).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/options.h"
#include "renderer/device_frame.h"
#include "renderer/renderer.h"
#include "scene/motion.h"

namespace penumbra {

struct FrameOptions {
    std::string scene = "cornell";
    std::string camera;                 // --camera as given, and parsed when it was given
    std::optional<Camera> parsedCamera;
    int cameraIndex = 0;
    std::string view;                   // --view: a named view of the scene (scene/named_views.h)
    std::vector<std::string> lights;    // --light as given, and parsed
    std::vector<Light> parsedLights;
    std::vector<std::string> lightFilters;  // --light-shadow N=MODE
    BuiltinOptions builtin;  // --strands
    // Time and motion (docs/cli.md): --time, --animation, --clamp, --sun-path, --light-path,
    // --camera-keys, --no-motion.
    double time = 0.0;
    AnimationOptions animation;
    MotionPaths motion;               // as given, and parsed
    ParsedMotionPaths parsedMotion;
};

// The frame inputs' option tables: scene camera and lights (`inputs`), time and motion (`motion`).
const OptionTable& frameInputOptions();
const OptionTable& motionOptions();

// The help of the positional scene argument.
std::string sceneArgumentHelp();
// The frame's defaults where they differ from RenderSettings' own: RSM GI and PCF shadows.
void setFrameDefaults(RenderSettings& settings);

// The cross-option rules and the values derived after parsing (AOV, DSM); warns once for a
// combination that works with a caveat. Throws std::invalid_argument with one line.
void checkFrameSettings(const FrameOptions& o, RenderSettings& settings);
// Loads the scene, applies the light overrides and picks the camera (settings already checked; the
// motion over the frame is frameMotion's). Throws std::invalid_argument / SceneError with one line.
PreparedFrame loadFrame(const FrameOptions& o);
// checkFrameSettings, loadFrame and the motion's checks: a frame without a device (dry runs).
PreparedFrame prepareFrame(const FrameOptions& o, RenderSettings& settings);

// The parts of loadFrame, for a viewer that changes options one at a time:
// the lights of `loaded` (a scene as loadScene returned it) after --light and --light-shadow;
std::vector<Light> frameLights(const FrameOptions& o, const Scene& loaded);
// the camera: --camera, else --view's, else the scene's camera --camera-index.
Camera frameCamera(const FrameOptions& o, const Scene& scene);

// What moves in the prepared frame (animation, paths, the built-in default motion); a path or an
// animation that does not fit the frame is refused naming its option.
SceneMotion checkedMotion(const FrameOptions& o, const PreparedFrame& f);
// Warns once when --time is given for a scene where nothing moves.
void warnIfStill(const FrameOptions& o, const SceneMotion& motion, const Scene& scene);
// checkedMotion, then warnIfStill (frame/frame_setup.h: the motion a device's frame built).
SceneMotion frameMotion(const FrameOptions& o, const PreparedFrame& f);
// The frame's inputs at time t.
FrameInputs frameInputs(const SceneMotion& motion, double t);

}  // namespace penumbra
