// The options that define one frame (scene, camera, lights, size, shadows, GI, DSM), shared by
// `render` and `bench`, and the preparation of the scene and camera they describe.
#pragma once
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/dsm_cli.h"
#include "render/renderer.h"

namespace penumbra {

struct FrameOptions {
    std::string scene = "cornell";
    std::string camera;
    int cameraIndex = 0;
    std::vector<std::string> lights;
    std::vector<std::string> lightFilters;  // --light-shadow N=MODE
    std::string aov = "final";
    BuiltinOptions builtin;  // --strands
};

void addFrameOptions(CLI::App& cmd, FrameOptions& o, RenderSettings& rs);

struct PreparedFrame {
    Scene scene;
    Camera camera;
};

// Checks the settings' combinations, loads the scene, applies light overrides, picks the camera.
// Throws std::invalid_argument / SceneError with one clear line.
PreparedFrame prepareFrame(const FrameOptions& o, RenderSettings& settings);

// The parts of prepareFrame, for a viewer that changes options one at a time:
// the cross-option rules and the values derived after parsing (AOV, DSM);
void checkFrameSettings(const FrameOptions& o, RenderSettings& settings);
// the lights of `loaded` (a scene as loadScene returned it) after --light and --light-shadow;
std::vector<Light> frameLights(const FrameOptions& o, const Scene& loaded);
// the camera: --camera, else the scene's camera --camera-index.
Camera frameCamera(const FrameOptions& o, const Scene& scene);

}  // namespace penumbra
