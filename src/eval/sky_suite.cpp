#include "eval/sky_suite.h"

#include <algorithm>

#include <fmt/format.h>

#include "lighting/lighting_options.h"

namespace penumbra {

bool hasSkyCase(const std::string& suiteScene) {
    return std::find(kSkySuiteScenes.begin(), kSkySuiteScenes.end(), suiteScene) != kSkySuiteScenes.end();
}

SkySettings suiteSky() {
    SkySettings sky;
    sky.kind = SkyKind::Analytic;
    sky.turbidity = kDefaultTurbidity;
    return sky;
}

std::vector<Light> skyOnlyLights(const std::vector<Light>& lights) {
    std::vector<Light> out = lights;
    for (Light& l : out) l.intensity = 0.0f;
    return out;
}

SkySettings skyOnlySky(const SkySettings& sky, const std::vector<Light>& lights) {
    SkySettings out = sky;
    if (sky.kind == SkyKind::Analytic) out.sunIlluminance = skySunIlluminance(sky, lights);
    return out;
}

GroundTruth sumOfTruths(const GroundTruth& sun, const GroundTruth& sky) {
    GroundTruth t;
    t.direct = sun.direct, t.indirect = sun.indirect, t.mask = sun.mask;
    for (size_t k = 0; k < t.direct.rgba.size(); ++k)
        t.direct.rgba[k] += sky.direct.rgba[k], t.indirect.rgba[k] += sky.indirect.rgba[k];
    t.final = t.direct;
    for (size_t k = 0; k < t.final.rgba.size(); ++k) t.final.rgba[k] += t.indirect.rgba[k];
    return t;
}

SkySuiteResult runSkyCase(vk::Context& ctx, const Scene& scene, const Camera& camera, const SkySettings& sky,
                          const SkyCaseTruths& truths, const RenderSettings& base, int frames,
                          const std::function<void(size_t, size_t, const std::string&)>& progress) {
    SkySuiteResult r;
    r.width = base.width, r.height = base.height, r.frames = frames, r.sky = sky;
    const GroundTruth sum = sumOfTruths(truths.sun, truths.sky);
    r.noiseSkyDirect = compareImages(truths.skySecond.direct, truths.sky.direct, truths.sky.mask).relL1;
    r.noiseSkyBounce = compareImages(truths.skySecond.indirect, truths.sky.indirect, truths.sky.mask).relL1;
    r.noiseFinal = compareImages(sumOfTruths(truths.sunSecond, truths.skySecond).final, sum.final, sum.mask).relL1;

    Scene skyOnlyScene = scene;
    skyOnlyScene.lights = skyOnlyLights(scene.lights);
    RenderSettings skyOnlyBase = base, fullBase = base;
    skyOnlyBase.lighting.sky = skyOnlySky(sky, scene.lights);
    fullBase.lighting.sky = sky;
    const std::vector<EvalVariant> skyOnlyVariants = suiteVariants(skyOnlyBase), fullVariants = suiteVariants(fullBase);
    const size_t n = skyOnlyVariants.size() + fullVariants.size();
    auto step = [&](size_t offset, const char* what) {
        return [&progress, offset, n, what](size_t i, size_t, const std::string& name) {
            if (progress) progress(offset + i, n, fmt::format("{} {}", what, name));
        };
    };
    std::vector<EvalRow> skyOnly =
        runEval(ctx, skyOnlyScene, camera, skyOnlyVariants, truths.sky, frames, step(0, "sky alone"));
    std::vector<EvalRow> full =
        runEval(ctx, scene, camera, fullVariants, sum, frames, step(skyOnlyVariants.size(), "sun and sky"));
    for (size_t i = 0; i < skyOnly.size(); ++i) r.rows.push_back({std::move(skyOnly[i]), std::move(full[i])});
    return r;
}

std::string formatSkySuiteTable(const std::vector<SkySuiteResult>& results) {
    constexpr const char* kRow = "| {:<8} | {:<4} | {:>16} | {:>17} | {:>10} | {:>10} | {:>11} | {:>9} |\n";
    std::string out = fmt::format(kRow, "scene", "GI", "reference", "ref noise d/b/f", "sky direct", "sky bounce",
                                  "bounce bias", "final");
    out += fmt::format(kRow, "--------", "----", "----------------", "----------------:", "---------:", "---------:",
                       "----------:", "--------:");
    for (const SkySuiteResult& s : results)
        for (const SkyTermRow& row : s.rows)
            out += fmt::format(kRow, s.scene, row.skyOnly.variant.technique,
                               fmt::format("{}x{} {} spp", s.width, s.height, s.spp),
                               fmt::format("{:.3f}/{:.3f}/{:.3f}", s.noiseSkyDirect, s.noiseSkyBounce, s.noiseFinal),
                               fmtValue(row.skyDirect().relL1), fmtValue(row.skyBounce().relL1),
                               fmtValue(100.0 * relativeBias(row.skyBounce()), "{:+.1f}%"),
                               fmtValue(row.final().relL1));
    return out;
}

nlohmann::json skySuiteJson(const std::vector<SkySuiteResult>& results) {
    // How each term was measured, for whoever reads the JSON without the source.
    const nlohmann::json method{
        {"sky_alone", fmt::format("every light's intensity 0; the analytic sky keeps the first directional light's "
                                  "illuminance as its own sun's ({}): the same sky",
                                  lightingOptions().flagOf<LightingSettings>(
                                      [](auto& s) -> auto& { return s.sky.sunIlluminance; }))},
        {"sky_direct", "renderer: final - indirect of two sky-alone renders in step (a difference of two renders); "
                       "reference: the sky-alone direct radiance"},
        {"sky_bounce", "renderer: the indirect image of the sky-alone render; reference: the sky-alone indirect "
                       "radiance, one bounce"},
        {"final", "renderer: one render with the lights and the sky; reference: the sum of the sun-only (sky none) "
                  "and sky-alone references"}};
    nlohmann::json out = nlohmann::json::array();
    for (const SkySuiteResult& s : results) {
        nlohmann::json rows = nlohmann::json::array();
        for (const SkyTermRow& row : s.rows) {
            const nlohmann::json skyOnly = evalRowsJson({row.skyOnly})[0], full = evalRowsJson({row.full})[0];
            rows.push_back({{"technique", row.skyOnly.variant.technique},
                            {"sky_direct", metricsJson(row.skyDirect())},
                            {"sky_bounce", metricsJson(row.skyBounce())},
                            {"final", metricsJson(row.final())},
                            {"sky_alone_render", skyOnly},
                            {"sun_and_sky_render", full}});
        }
        out.push_back({{"scene", s.scene}, {"sky", skyText(s.sky)}, {"width", s.width}, {"height", s.height},
                       {"spp", s.spp}, {"frames", s.frames}, {"method", method},
                       {"reference_noise_rel_l1",
                        {{"sky_direct", s.noiseSkyDirect}, {"sky_bounce", s.noiseSkyBounce}, {"final", s.noiseFinal}}},
                       {"rows", rows}});
    }
    return out;
}

}  // namespace penumbra
