// `penumbra eval SCENE --hair`: the shadow techniques for hair against the path tracer, which traces
// the strands as ribbons of their opacity (reference/ray_scene.h). Two figures per technique:
//  - the hair image: final radiance (direct light: no GI on either side) against the anti-aliased
//    reference, over every pixel with geometry and over the pixels where the camera sees hair;
//  - the floor's shadow transmittance under the hair, the clean figure for the shadow alone:
//    T = shadow AOV with the strands / shadow AOV with the strands removed (the visibility of the
//    light at the opaque surface, behind any hair the camera sees), for the GPU and the reference
//    alike, over the floor pixels in the hair's shadow that the opaque casters leave lit.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "eval/eval.h"

namespace penumbra {

// Each opaque shadow filter (hair an opaque caster in the ordinary shadow map), then the volumetric
// techniques (deep shadow maps). A further volumetric technique is one more entry in this list.
std::vector<EvalVariant> hairEvalVariants(const RenderSettings& base);

// The reference's side: its radiance and mask, the pixels where the camera sees hair, and the
// floor transmittance T (ref. shadow with strands / without) with the pixels where T is measured.
struct HairGroundTruth {
    ImageF final;
    std::vector<uint8_t> mask;          // pixels with geometry
    std::vector<uint8_t> hairPixels;    // the camera's paths stop at a strand in >= kHairPixelAlpha of them
    ImageF transmittance;               // grey: T per pixel (0 where the strands removed leave no light)
    std::vector<uint8_t> shadowPixels;  // where T is compared (floorShadowPixels)
    double noiseFinal = 0.0;            // the reference's own relative L2 error of `final`
};
constexpr float kHairPixelAlpha = 0.1f;

// From the reference's images of the scene (final radiance, mask, hair and shadow AOVs) and its
// shadow AOV without the strands, and the floor pixels (floorPixels).
HairGroundTruth makeHairGroundTruth(const ImageF& final, const std::vector<uint8_t>& mask, const ImageF& hair,
                                    const ImageF& shadowWith, const ImageF& shadowWithout,
                                    const std::vector<uint8_t>& floor, double noiseFinal);

// T = with / without, channel 0 of two shadow AOVs (0 where `without` is 0).
ImageF transmittanceImage(const ImageF& with, const ImageF& without);

// The pixels where the floor's transmittance under the hair is measured: the floor (`floor`, from the
// renderer's normal AOV), lit in full without the strands (reference shadow 1 in every pixel within
// `margin` pixels, so that no row's shadow-map edge of the head enters) and in the hair's shadow
// (reference T < 0.99).
std::vector<uint8_t> floorShadowPixels(const ImageF& refWithout, const ImageF& refTransmittance,
                                       const std::vector<uint8_t>& floor, int margin = 2);

struct HairEvalRow {
    EvalVariant variant;
    double frameMs = 0.0;                        // median GPU time of the frame
    ImageMetrics image, hair, transmittance;     // final radiance (all, hair pixels); floor T
    // What the frame dropped (its pools full): a row with drops measures the pool, not the technique.
    std::vector<std::string> warnings;
    ImageF finalImage, floorImage;  // final radiance and T, kept for figure variants only
};

// Renders each variant on the scene and on the scene without its strands (final radiance `frames`
// times for the timing; shadow AOVs) and measures it against `truth`. `truth.shadowPixels` must be
// set (runHairEval's caller builds it with floorPixels of the same renderer).
std::vector<HairEvalRow> runHairEval(vk::Context& ctx, const Scene& scene, const Camera& camera,
                                     const std::vector<EvalVariant>& variants, const HairGroundTruth& truth,
                                     int frames, const std::function<void(size_t, size_t, const std::string&)>& progress);

// The floor's pixels: the opaque surface (rendered without strands) faces up (normal AOV y > 0.9) at
// the scene's lowest height (depth AOV; not the top of the head).
std::vector<uint8_t> floorPixels(vk::Context& ctx, const Scene& scene, const Camera& camera, const RenderSettings& base);

// The scene without its hair strands (the "removed" render of the transmittance).
Scene withoutStrands(const Scene& scene);

// Markdown table: technique, settings, GPU ms (blank unless `gpu`), relative L2 of the image and of
// its hair pixels, relative L2 and mean bias (GPU - reference, in transmittance) of the floor's T.
std::string formatHairEvalTable(const std::vector<HairEvalRow>& rows, bool gpu);

// The side-by-side figure (evalFigure's layout): columns reference and the figure variants (PCF and
// DSM); rows final radiance (at `exposure`), floor transmittance T (grey, 1 = white after the tone
// mapper), |T - T_ref| over the measured floor pixels (`heatScale`: the heat map's top).
std::vector<uint8_t> hairEvalFigure(const std::vector<HairEvalRow>& rows, const HairGroundTruth& truth, float exposure,
                                    uint32_t maxCellWidth, double& heatScale, uint32_t& width, uint32_t& height);
nlohmann::json hairEvalRowsJson(const std::vector<HairEvalRow>& rows);

}  // namespace penumbra
