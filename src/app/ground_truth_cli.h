// The ground-truth commands (docs/evaluation.md): `reference` (CPU path tracer), `compare`
// (error metrics and heat map of two EXR images) and `eval` (every technique against the reference).
#pragma once
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/frame_cli.h"
#include "eval/suite.h"
#include "lighting/lighting_settings.h"
#include "reference/path_tracer.h"
#include "vk/context.h"

namespace penumbra {

// The scene, camera and lights of a reference render (the subset of FrameOptions it honours).
struct ReferenceCliOptions {
    FrameOptions frame;
    std::string output = "reference.exr";
    ReferenceAov aov = ReferenceAov::Final;
    float exposure = 1.0f;
    ReferenceSettings settings;
    // `reference`'s sky, by the lighting module's rows (settings.sky takes it, Auto resolved).
    LightingSettings lighting;
};
// The option tables of the ground-truth commands: size and sampling (`reference` and `eval`), the
// output of `reference`, `compare`'s and `eval`'s own.
const OptionTable& referenceSceneOptions();
const OptionTable& referenceCommandOptions();
const OptionTable& compareCommandOptions();
const OptionTable& evalCommandOptions();

// Scene, camera, lights, size and sampling options (shared by `reference` and `eval`).
void addReferenceSceneOptions(CLI::App& cmd, ReferenceCliOptions& options);
CLI::App* addReferenceCommand(CLI::App& app, ReferenceCliOptions& options);
int runReferenceCommand(const ReferenceCliOptions& options, bool dryRun = false);

struct CompareCliOptions {
    std::string a, b;     // test image, reference
    std::string mask;     // "" = every pixel
    std::string heatMap;  // -o: PNG heat map, "" = none
    double heatMax = 0.0; // 0 = the 99th percentile of the error
    bool json = false;
};
CLI::App* addCompareCommand(CLI::App& app, CompareCliOptions& options);
int runCompareCommand(const CompareCliOptions& options, bool dryRun = false);

struct EvalCliOptions {
    ReferenceCliOptions reference;  // scene, camera, lights, size, spp, bounces, seed
    std::string referenceDir;       // cache of the reference render ("" = render it every time)
    std::string json;
    std::string images;             // directory for the side-by-side figure
    int frames = kSuiteFrames;      // a still view: the GI history accumulates them
    float indirectExposure = 4.0f;
    uint32_t figureCellWidth = 320;  // the figure's cells are shrunk to at most this width
    std::string command;            // recorded in the JSON
    bool suite = false;             // --suite: the GI evaluation suite instead of one scene
    std::string assets = "../shared/assets";  // --suite: the folder holding sponza/ and VC/
    std::vector<std::string> suiteScenes;     // --scenes: a subset of the suite (empty = all)
    SuiteCases suiteCases = SuiteCases::All;  // --suite-cases: sun-only, sky or both
    bool hair = false;              // --hair: the hair evaluation (eval/hair_eval.h) instead of GI modes
    bool bouncesGiven = false;      // --bounces was on the command line (--hair ignores it)
};
CLI::App* addEvalCommand(CLI::App& app, EvalCliOptions& options);
int runEvalCommand(const EvalCliOptions& options, const vk::ContextOptions& vkOptions, bool dryRun = false);

// Loads the scene and camera the way `render` does (shared by reference and eval).
PreparedFrame prepareReferenceFrame(const ReferenceCliOptions& options);

}  // namespace penumbra
