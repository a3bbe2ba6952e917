// `penumbra stability SCENE [render options] --frames N [--json F] [--all]`: temporal flicker of the
// techniques over a slow motion, against the path tracer's own figure (docs/evaluation.md).
#pragma once
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/frame_cli.h"
#include "vk/context.h"

namespace penumbra {

struct StabilityOptions {
    FrameOptions frame;
    int frames = 6;
    // Still frames at the motion's start before the measured ones: the GI history settles, so the
    // figure is the flicker of a history in motion, not of one being filled (0: none).
    int warmup = 32;
    double fps = 30.0;
    std::string json;
    bool all = false;             // every shadow filter and GI mode
    uint32_t referenceSpp = 16;   // the path tracer's first spp (doubled until the figure settles)
    uint32_t referenceMaxSpp = 256;
    bool reference = true;        // --no-reference: skip the path tracer's floor
    std::string change;           // --change: measure the response to it instead (app/response.h)
    int settle = 64;              // --change: still frames before and after it; --ghosting: of each still image
    bool ghosting = false;        // --ghosting: the GI's ghosting behind moving geometry (app/ghosting.h)
    std::string command;
};

// The options of `stability` itself (frames, fps, JSON, the path tracer's floor).
const OptionTable& stabilityCommandOptions();
CLI::App* addStabilityCommand(CLI::App& app, StabilityOptions& options, RenderSettings& settings);
int runStability(const StabilityOptions& options, const vk::ContextOptions& vkOptions, RenderSettings settings,
                 bool dryRun = false);

// Flicker of a sequence of luminance images (each `pixels` values, NaN = not measured): the mean over
// interior frames and measured pixels of |I_t - (I_{t-1} + I_{t+1}) / 2|, divided by the mean of I.
double flicker(const std::vector<std::vector<float>>& luminance);
// The RMS form: sqrt(mean of (I_t - (I_{t-1} + I_{t+1}) / 2)^2) / mean(I).
double flickerRms(const std::vector<std::vector<float>>& luminance);
// The RMS form without the noise of two independent renders `a` and `b` of the same frames: the mean
// of the products of their second differences (an unbiased estimate of the noise-free mean square).
double flickerRmsNoiseFree(const std::vector<std::vector<float>>& a, const std::vector<std::vector<float>>& b);

}  // namespace penumbra
