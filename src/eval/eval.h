// `penumbra eval`: every GI mode and shadow filter rendered in one Vulkan context and measured
// against the path-traced reference: the table that tells a user which technique to pick.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "eval/compare.h"
#include "renderer/renderer.h"
#include "vk/context.h"

namespace penumbra {

struct EvalVariant {
    std::string technique;  // "rsm interpolated", "lpv", "shadow pcss", ...
    std::string settings;   // human-readable parameters
    RenderSettings render;
    bool figure = false;    // shown in the side-by-side figure (RSM and LPV defaults)
};

// The GI modes (none, RSM full and interpolated, LPV at three settings) with hard shadows, then
// every other shadow filter without GI. `base` provides the size and everything not varied. `sun`
// (the scene has a shadowed directional light) adds RSM full with one shadow cascade.
std::vector<EvalVariant> evalVariants(const RenderSettings& base, bool sun = false);

// The reference's radiance: direct, indirect, final = direct + indirect; mask = pixels with geometry.
// noise*: the reference's own relative L2 error, sqrt(sum var / sum B^2) over the mask from its
// per-pixel variance estimates: a perfect technique would score about this much.
struct GroundTruth {
    ImageF direct, indirect, final;
    std::vector<uint8_t> mask;
    double noiseFinal = 0.0, noiseIndirect = 0.0;
    ImageF shadow, hair;  // the reference's shadow and hair AOVs (path_tracer.h), for `eval --hair`
    double noiseHair = 0.0;  // relative L2 noise of `final` over the hair pixels (eval/hair_eval.h)
};

struct EvalRow {
    EvalVariant variant;
    double frameMs = 0.0;  // median GPU time of the whole frame (sum of its passes)
    ImageMetrics direct, total, indirect;
    ImageF final, indirectImage;  // kept for figure variants only
};

// Renders each variant (Aov::Final `frames` times for the timing, then Aov::Indirect once) and
// compares it with the reference over the mask. `progress(i, n, name)` is called before each.
std::vector<EvalRow> runEval(vk::Context& ctx, const Scene& scene, const Camera& camera,
                             const std::vector<EvalVariant>& variants, const GroundTruth& truth, int frames,
                             const std::function<void(size_t, size_t, const std::string&)>& progress);

// The table as text: technique, settings, GPU ms (blank unless `gpu`), relative L2 of direct,
// total (and its SSIM) and indirect radiance, indirect relative bias.
std::string formatEvalTable(const std::vector<EvalRow>& rows, bool gpu);
nlohmann::json evalRowsJson(const std::vector<EvalRow>& rows);

// Relative bias sum(A - B) / sum(B) over the compared pixels and channels.
double relativeBias(const ImageMetrics& m);
// Every metric as JSON (non-finite values as null); a table cell ("-" for NaN); the median (NaN if none).
nlohmann::json metricsJson(const ImageMetrics& m);
std::string fmtValue(double v, const char* spec = "{:.3f}");
double medianOf(std::vector<double> v);

// Side by side (RGBA8): a column for the reference and one per figure variant; rows: final radiance
// (tone-mapped at `exposure`), indirect radiance (at `indirectExposure`), the indirect error heat
// map (one scale for every column, returned in `heatScale`; the reference column shows the ramp).
// Cells wider than `maxCellWidth` are box-filtered down by an integer factor.
std::vector<uint8_t> evalFigure(const std::vector<EvalRow>& rows, const GroundTruth& truth, float exposure,
                                float indirectExposure, uint32_t maxCellWidth, double& heatScale, uint32_t& width,
                                uint32_t& height);

}  // namespace penumbra
