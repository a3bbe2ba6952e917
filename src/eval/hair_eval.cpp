#include "eval/hair_eval.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "dsm/deep_shadow_maps.h"
#include "dsm/dsm_technique.h"
#include "dsm/translucency.h"
#include "core/gpu_scene.h"

namespace penumbra {
namespace {

// Clears the pixels of `masks` where `image` is not finite (they would make every metric NaN); the
// warning that says so, or "" when there are none.
std::string leaveOutNonFinite(const ImageF& image, std::vector<std::vector<uint8_t>*> masks) {
    size_t count = 0, first = 0;
    for (size_t p = 0; p < image.rgba.size() / 4; ++p) {
        if (std::isfinite(image.rgba[p * 4] + image.rgba[p * 4 + 1] + image.rgba[p * 4 + 2])) continue;
        if (count++ == 0) first = p;
        for (std::vector<uint8_t>* m : masks) (*m)[p] = 0;
    }
    return count ? fmt::format("{} non-finite pixel(s) in the final image (the first at {}, {}), left out of the "
                               "image metrics", count, first % image.width, first / image.width)
                 : std::string();
}

}  // namespace

std::vector<EvalVariant> hairEvalVariants(const RenderSettings& base) {
    std::vector<EvalVariant> v;
    for (const std::string& name : shadowFilterNames()) {
        EvalVariant s{"shadow " + name, "hair opaque in the shadow map", base, name == "pcf"};
        s.render.gi = GiMode::None;
        s.render.shadow.filter = parseShadowFilter(name, "eval");
        v.push_back(s);
    }
    // `--shadow dsm`: deep shadow maps for the hair, the CLI's default filter (PCF) for opaque casters.
    EvalVariant dsm{"shadow dsm", "", base, true};
    dsm.render.gi = GiMode::None;
    dsm.render.shadow.filter = ShadowFilter::Pcf;
    dsm.render.dsm.enabled = true;
    dsm.settings = fmt::format("DSM {}-node lists, {}-texel filter; pcf", dsm.render.dsm.maxList,
                               dsm.render.dsm.filterWidth);
    v.push_back(dsm);
    // `--shadow dom`: deep opacity maps, the volumetric technique DSM is compared with.
    EvalVariant dom = dsm;
    dom.technique = "shadow dom";
    dom.render.dsm.opacityMaps = true;
    dom.settings = fmt::format("DOM {} layers, {}-texel filter; pcf", DOM_LAYERS, dom.render.dsm.filterWidth);
    v.push_back(dom);
    return v;
}

ImageF transmittanceImage(const ImageF& with, const ImageF& without) {
    ImageF t{with.width, with.height, std::vector<float>(with.rgba.size(), 0.0f)};
    for (size_t i = 0; i < t.rgba.size() / 4; ++i) {
        const float w = without.rgba[i * 4], v = without.rgba[i * 4] > 0.0f ? with.rgba[i * 4] / w : 0.0f;
        std::fill_n(t.rgba.begin() + i * 4, 3, v);
        t.rgba[i * 4 + 3] = 1.0f;
    }
    return t;
}

std::vector<uint8_t> floorShadowPixels(const ImageF& refWithout, const ImageF& refTransmittance,
                                       const std::vector<uint8_t>& floor, int margin) {
    const int w = int(refWithout.width), h = int(refWithout.height);
    std::vector<uint8_t> out(size_t(w) * h, 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            if (!floor[i] || refTransmittance.rgba[i * 4] >= 0.99f) continue;
            bool lit = true;  // the opaque casters leave the whole neighbourhood lit
            for (int dy = -margin; dy <= margin && lit; ++dy)
                for (int dx = -margin; dx <= margin && lit; ++dx) {
                    const int nx = std::clamp(x + dx, 0, w - 1), ny = std::clamp(y + dy, 0, h - 1);
                    lit = refWithout.rgba[(size_t(ny) * w + nx) * 4] >= 0.999f;
                }
            out[i] = lit;
        }
    return out;
}

HairGroundTruth makeHairGroundTruth(const ImageF& final, const std::vector<uint8_t>& mask, const ImageF& hair,
                                    const ImageF& shadowWith, const ImageF& shadowWithout,
                                    const std::vector<uint8_t>& floor, double noiseFinal) {
    HairGroundTruth t{final, mask, std::vector<uint8_t>(mask.size()), transmittanceImage(shadowWith, shadowWithout),
                      {}, noiseFinal};
    for (size_t i = 0; i < mask.size(); ++i) t.hairPixels[i] = hair.rgba[i * 4] >= kHairPixelAlpha;
    t.shadowPixels = floorShadowPixels(shadowWithout, t.transmittance, floor);
    return t;
}

Scene withoutStrands(const Scene& scene) {
    Scene bare = scene;
    bare.strands.clear();
    bare.strandPoints.clear();
    return bare;
}

std::vector<uint8_t> floorPixels(vk::Context& ctx, const Scene& scene, const Camera& camera, const RenderSettings& base) {
    const Scene bare = withoutStrands(scene);
    GpuScene gpuScene(ctx, bare);
    RenderSettings s = base;
    s.aov = Aov::Normal;
    s.gi = GiMode::None;
    Renderer r(ctx, gpuScene, s, 1);
    r.render(camera);
    const std::vector<float> normal = r.readHdr();
    r.setAov(Aov::Depth);  // distance to the eye: the height of the pixel's surface
    r.render(camera);
    const std::vector<float> distance = r.readHdr();
    // The camera's rays as the renderer's (glm::lookAt, vertical fovy, top row first).
    const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up)), up = glm::cross(right, forward);
    const float tanHalf = std::tan(0.5f * camera.fovy), aspect = float(s.width) / float(s.height);
    const float lowest = scene.bounds.min.y + 1e-3f * glm::length(scene.bounds.max - scene.bounds.min);
    std::vector<uint8_t> out(size_t(s.width) * s.height);
    for (uint32_t y = 0; y < s.height; ++y)
        for (uint32_t x = 0; x < s.width; ++x) {
            const size_t i = size_t(y) * s.width + x;
            const glm::vec3 dir = glm::normalize(forward + ((x + 0.5f) / s.width * 2.0f - 1.0f) * tanHalf * aspect * right +
                                                 (1.0f - (y + 0.5f) / s.height * 2.0f) * tanHalf * up);
            out[i] = normal[i * 4 + 1] > 0.9f && camera.eye.y + distance[i * 4] * dir.y < lowest;
        }
    return out;
}

std::vector<HairEvalRow> runHairEval(vk::Context& ctx, const Scene& scene, const Camera& camera,
                                     const std::vector<EvalVariant>& variants, const HairGroundTruth& truth,
                                     int frames, const std::function<void(size_t, size_t, const std::string&)>& progress) {
    // One upload of each scene; each variant is a settings change of its renderer.
    const Scene bare = withoutStrands(scene);
    GpuScene hairScene(ctx, scene), bareScene(ctx, bare);
    std::unique_ptr<Renderer> hair, removed;
    auto use = [&ctx](std::unique_ptr<Renderer>& r, GpuScene& g, const RenderSettings& s) -> Renderer& {
        if (r) r->apply(s);
        else r = std::make_unique<Renderer>(ctx, g, s, 1);
        return *r;
    };
    std::vector<HairEvalRow> rows;
    for (size_t i = 0; i < variants.size(); ++i) {
        const EvalVariant& v = variants[i];
        if (progress) progress(i, variants.size(), v.technique);
        RenderSettings s = v.render;
        s.aov = Aov::Final;
        Renderer& r = use(hair, hairScene, s);
        std::vector<double> ms;
        for (int f = 0; f < std::max(frames, 1); ++f) {
            r.render(camera);
            if (f > 0 || frames <= 1) ms.push_back(r.frameTimings().gpuMs);  // the first frame warms caches
        }
        const ImageF final{s.width, s.height, r.readHdr()};
        std::vector<std::string> warnings;
        if (const CameraTranslucency* t = r.find<TranslucencyTechnique>()->translucency())
            warnings = translucencyWarnings(t->readStats(r.commands()));
        const DeepShadowMaps& maps = r.find<DsmTechnique>()->maps();
        if (maps.active())
            for (const std::string& w : dsmWarnings(maps.readStats(r.commands()))) warnings.push_back(w);
        r.setAov(Aov::Shadow);
        r.render(camera);
        const ImageF with{s.width, s.height, r.readHdr()};
        s.aov = Aov::Shadow;
        // Without strands a DSM has nothing to hold (transmittance 1): the same frame without one.
        // (It is also required: a DSM build with no hair and no BLEND mesh binds a null pipeline.)
        s.dsm.enabled = false;
        Renderer& b = use(removed, bareScene, s);
        b.render(camera);
        const ImageF without{s.width, s.height, b.readHdr()};
        std::vector<uint8_t> finite = truth.mask, finiteHair = truth.hairPixels;
        if (std::string w = leaveOutNonFinite(final, {&finite, &finiteHair}); !w.empty()) warnings.push_back(w);
        HairEvalRow row{v, medianOf(ms), {}, {}, {}, std::move(warnings), {}, {}};
        ImageF transmittance = transmittanceImage(with, without);
        row.image = compareImages(final, truth.final, finite);
        row.hair = compareImages(final, truth.final, finiteHair);
        row.transmittance = compareImages(transmittance, truth.transmittance, truth.shadowPixels);
        if (v.figure) row.finalImage = final, row.floorImage = std::move(transmittance);
        rows.push_back(std::move(row));
    }
    return rows;
}

std::string formatHairEvalTable(const std::vector<HairEvalRow>& rows, bool gpu) {
    constexpr const char* kRow = "| {:<12} | {:<38} | {:>8} | {:>8} | {:>7} | {:>10} | {:>10} | {:>9} |\n";
    std::string out = fmt::format(kRow, "technique", "settings", "GPU ms", "image L2", "hair L2", "floor T L2",
                                  "floor T bias", "floor T");
    out += fmt::format(kRow, std::string(12, '-'), std::string(38, '-'), "-------:", "-------:", "------:", "---------:",
                       "-----------:", "--------:");
    for (const HairEvalRow& r : rows)
        out += fmt::format(kRow, r.variant.technique, r.variant.settings, gpu ? fmtValue(r.frameMs) : "-",
                           fmtValue(r.image.relL2), fmtValue(r.hair.relL2), fmtValue(r.transmittance.relL2),
                           fmtValue(r.transmittance.meanBias, "{:+.3f}"),
                           fmtValue(r.transmittance.refMean + r.transmittance.meanBias));
    return out;
}

std::vector<uint8_t> hairEvalFigure(const std::vector<HairEvalRow>& rows, const HairGroundTruth& truth, float exposure,
                                    uint32_t maxCellWidth, double& heatScale, uint32_t& width, uint32_t& height) {
    // evalFigure's second and third rows show the transmittance in place of the indirect light.
    std::vector<EvalRow> shown;
    for (const HairEvalRow& r : rows)
        if (r.variant.figure) shown.push_back({r.variant, r.frameMs, {}, {}, {}, r.finalImage, r.floorImage});
    const GroundTruth t{{}, truth.transmittance, truth.final, truth.shadowPixels};
    return evalFigure(shown, t, exposure, 1.0f, maxCellWidth, heatScale, width, height);
}

nlohmann::json hairEvalRowsJson(const std::vector<HairEvalRow>& rows) {
    nlohmann::json out = nlohmann::json::array();
    for (const HairEvalRow& r : rows)
        out.push_back({{"technique", r.variant.technique},
                       {"settings", r.variant.settings},
                       {"frame_ms", std::isfinite(r.frameMs) ? nlohmann::json(r.frameMs) : nlohmann::json(nullptr)},
                       {"image", metricsJson(r.image)},
                       {"hair_pixels", metricsJson(r.hair)},
                       {"floor_transmittance", metricsJson(r.transmittance)},
                       {"warnings", r.warnings}});
    return out;
}

}  // namespace penumbra
