// The options that define one frame (scene, camera, lights, size, shadows, GI, DSM), shared by
// `render` and `bench`, and the preparation of the scene and camera they describe.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/dsm_cli.h"
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

void addFrameOptions(CLI::App& cmd, FrameOptions& o, RenderSettings& rs);
// The time and motion options alone (also on `reference` and `eval`).
void addMotionOptions(CLI::App& cmd, FrameOptions& o);

// Checks the settings' combinations, loads the scene, applies light overrides, picks the camera.
// Throws std::invalid_argument / SceneError with one clear line.
PreparedFrame prepareFrame(const FrameOptions& o, RenderSettings& settings);

// The parts of prepareFrame, for a viewer that changes options one at a time:
// the cross-option rules and the values derived after parsing (AOV, DSM);
void checkFrameSettings(const FrameOptions& o, RenderSettings& settings);
// the lights of `loaded` (a scene as loadScene returned it) after --light and --light-shadow;
std::vector<Light> frameLights(const FrameOptions& o, const Scene& loaded);
// the camera: --camera, else --view's, else the scene's camera --camera-index.
Camera frameCamera(const FrameOptions& o, const Scene& scene);

// What moves in the prepared frame (animation, paths, the built-in default motion); warns once when
// --time is given for a scene where nothing moves.
SceneMotion frameMotion(const FrameOptions& o, const PreparedFrame& f);
// The frame's inputs at time t.
FrameInputs frameInputs(const SceneMotion& motion, double t);

}  // namespace penumbra
