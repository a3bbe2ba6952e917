// The sky cases of `penumbra eval --suite` (docs/evaluation.md): the street, Sponza and VC views with
// their sun and the analytic sky, each term measured on its own against the path tracer. Light adds
// linearly, so every image is rendered twice, once with the sky off (the suite's sun-only case) and
// once with the lights off and the sky kept (the sky alone); the renderer's final image is one render
// with both, compared with the sum of the two references.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/sky.h"
#include "eval/eval.h"
#include "eval/suite.h"

namespace penumbra {

// The suite scenes that have a sky case (outdoor views with a sun), in the suite's order.
inline const std::vector<std::string> kSkySuiteScenes{"street", "sponza", "vc"};
bool hasSkyCase(const std::string& suiteScene);
// The sky of the sky cases: the analytic sky at its default turbidity, driven by the view's sun.
SkySettings suiteSky();

// The sky alone: every light's intensity 0, and the sky the same sky. The analytic sky follows the
// first directional light, whose brightness it keeps as its own sun's illuminance
// (SkySettings::sunIlluminance) while the light itself lights nothing.
std::vector<Light> skyOnlyLights(const std::vector<Light>& lights);
SkySettings skyOnlySky(const SkySettings& sky, const std::vector<Light>& lights);

// The reference of sun and sky together: the sum of the sun-only and sky-only references (their
// direct and indirect radiance; the noise figures are left 0, the suite measures noise by seeds).
GroundTruth sumOfTruths(const GroundTruth& sun, const GroundTruth& sky);

// One technique's terms. Renderer side: sky_direct = final - indirect of the two sky-only renderers
// in step (runEval: the difference of two renders), sky_bounce = their indirect image, final = one
// render with sun and sky. Reference side: the sky-only reference's direct and indirect (one bounce),
// and the sum of the two references.
struct SkyTermRow {
    EvalRow skyOnly;  // the sky-only renders against the sky-only reference
    EvalRow full;     // sun and sky against the sum of the references
    const ImageMetrics& skyDirect() const { return skyOnly.direct; }
    const ImageMetrics& skyBounce() const { return skyOnly.indirect; }
    const ImageMetrics& final() const { return full.total; }
};

struct SkySuiteResult {
    std::string scene;
    uint32_t width = 0, height = 0, spp = 0;
    int frames = 0;
    SkySettings sky;
    // Relative L1 between the references of two seeds: sky-only direct and indirect, and the summed final.
    double noiseSkyDirect = 0.0, noiseSkyBounce = 0.0, noiseFinal = 0.0;
    std::vector<SkyTermRow> rows;  // suiteVariants' order: rsm, lpv
};

struct SkyCaseTruths {
    GroundTruth sun, sky;                  // seed N
    GroundTruth sunSecond, skySecond;      // seed N + 1, for the noise figures
};

// Renders suiteVariants(base) with `sky` twice (`frames` still frames each, the GI history accumulating
// them): the sky alone (skyOnlyLights, skyOnlySky) and `scene` with its lights and the sky.
SkySuiteResult runSkyCase(vk::Context& ctx, const Scene& scene, const Camera& camera, const SkySettings& sky,
                          const SkyCaseTruths& truths, const RenderSettings& base, int frames,
                          const std::function<void(size_t, size_t, const std::string&)>& progress);

// Markdown table: per scene and technique, relative L1 of the sky's direct light, of its bounce (and
// the bounce's energy bias) and of the final image, with the references' noise.
std::string formatSkySuiteTable(const std::vector<SkySuiteResult>& results);
nlohmann::json skySuiteJson(const std::vector<SkySuiteResult>& results);

}  // namespace penumbra
