// `penumbra eval --suite`: the GI evaluation suite (docs/evaluation.md). Five scenes
// (cornell, street, room built in; Sponza and VC from the assets) at fixed sizes and path counts,
// RSM and LPV at their defaults against the one-bounce path tracer: indirect relative L1 and energy
// bias per technique per scene, with the reference's own noise (relative L1 between two seeds).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "eval/eval.h"

namespace penumbra {

struct SuiteScene {
    std::string name;                 // table row
    std::string scene;                // built-in name or glTF path
    std::string camera;               // camera override as the CLI takes it, "" = the scene's
    std::vector<std::string> lights;  // light overrides as the CLI takes them, empty = the scene's
    uint32_t width = 0, height = 0, spp = 0;
};

// The five scenes; glTF paths under `assets` (the folder holding sponza/ and VC/). `only`: names to
// keep (empty = all); an unknown name throws std::invalid_argument.
// Still frames rendered per view: the GI history accumulates them (the temporal GI's converged
// estimate, which is what a still view shows after about a second).
inline constexpr int kSuiteFrames = 32;

// Which cases `eval --suite` runs (--suite-cases): the sun-only cases of the five scenes, the sky
// cases of the outdoor ones (eval/sky_suite.h), or both.
enum class SuiteCases { All, Sun, Sky };

std::vector<SuiteScene> suiteScenes(const std::string& assets, const std::vector<std::string>& only = {});

// RSM (interpolated) and LPV at their default settings, hard shadows, both kept for the figure.
std::vector<EvalVariant> suiteVariants(const RenderSettings& base);

struct SuiteResult {
    std::string scene;
    uint32_t width = 0, height = 0, spp = 0;
    double noiseL1 = 0.0;      // indirect relative L1 between the references of two seeds
    std::vector<EvalRow> rows;  // suiteVariants' order: rsm, lpv
    double ceilingRsm = -1.0, ceilingLpv = -1.0;  // cornell: mean indirect on the ceiling / reference's
};

// The Markdown table: per scene the reference's size, paths and noise, then per technique the
// indirect relative L1 and the energy bias (mean(A - B) / mean(B)).
std::string formatSuiteTable(const std::vector<SuiteResult>& results);
nlohmann::json suiteJson(const std::vector<SuiteResult>& results);

// Mean of `a` over the pixels where `region` is non-zero, over the mean of `b` there (NaN if none).
double regionRatio(const ImageF& a, const ImageF& b, const std::vector<uint8_t>& region);

// Exposure that maps the log-average luminance of `image` over `mask` to 0.18 (Reinhard's key):
// figures of scenes with photometric lights (683 lm/W) come out neither white nor black.
float autoExposure(const ImageF& image, const std::vector<uint8_t>& mask);

}  // namespace penumbra
