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

// Parses the AOV and checks the settings' combinations (no file or GPU work); throws
// std::invalid_argument with one line. prepareFrame calls it first.
void checkFrameSettings(const FrameOptions& o, RenderSettings& settings);

// Checks the settings' combinations, loads the scene, applies light overrides, picks the camera.
// Throws std::invalid_argument / SceneError with one clear line.
PreparedFrame prepareFrame(const FrameOptions& o, RenderSettings& settings);

}  // namespace penumbra
