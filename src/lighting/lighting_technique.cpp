#include "lighting/lighting_technique.h"

#include "core/gpu_scene.h"
#include "core/names.h"
#include "lighting/lighting_options.h"

#include <algorithm>
#include <cmath>

namespace penumbra {

CameraTechnique::CameraTechnique(const TechniqueBuild& b)
    : gbuffer_(b.alloc, b.scene.meshes(), b.core.width, b.core.height, b.drawLayout, b.core.cameraPath,
               !b.core.translucency, b.core.computeRaster,
               // opaque hair ribbons are drawn into the depth afterwards (src/dsm)
               !b.core.translucency && !b.scene.scene().strands.empty()) {
    noIds_ = vk::Image(b.alloc, {VK_FORMAT_R32_UINT, 1, 1, 1,
                                 VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, "no-ids"});
    const uint32_t zero = 0;
    b.cmd.uploadImage(noIds_, &zero, sizeof(zero));
}

// The classic G-buffer has no triangle IDs: readers of "gbuffer.ids" (velocity, temporal GI) get a
// 1x1 zero image, published here so that every technique after the camera finds it.
void CameraTechnique::addPasses(const FrameContext& f) {
    gbuffer_.addTo(f.graph, f.slot);
    if (!f.graph.has(names::kGbufferIds)) f.graph.publish(names::kGbufferIds, f.graph.import(noIds_));
}

LightingTechnique::LightingTechnique(const TechniqueBuild& b, const LightingSettings& settings)
    : board_(b.board), irradiance_(b.alloc, b.core.width, b.core.height), lighting_(b.alloc, b.core.width, b.core.height),
      debugView_(b.alloc.context()), tonemap_(b.alloc, b.core.width, b.core.height), settings_(settings),
      warnings_(b.warnings), gpuSky_(b.alloc, b.cmd), exposure_(b.alloc, b.core.width, b.core.height) {
    noIndirect_ = vk::Image(b.alloc, {VK_FORMAT_R16G16B16A16_SFLOAT, 1, 1, 1,
                                      VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, "no-indirect"});
    noSky_ = vk::Image(b.alloc, {VK_FORMAT_R16G16B16A16_SFLOAT, 1, 1, 1,
                                 VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, "no-sky"});
    const uint64_t zero = 0;
    b.cmd.uploadImage(noIndirect_, &zero, sizeof(zero));
    b.cmd.uploadImage(noSky_, &zero, sizeof(zero));
    b.board.put(names::kHdrImage, &lighting_.hdr, this);
    b.board.put(names::kLdrImage, &tonemap_.ldr, this);
    b.board.put(names::kSkyLight, &skyLight_, this);
    refreshSky(b.lights);  // at build: a map that cannot be read fails before the first frame
}

LightingTechnique::~LightingTechnique() { board_.dropOwner(this); }

gpu::TonemapPush LightingTechnique::tonemapParams(const FrameContext& f) const {
    const float depthFar = f.sceneFar;
    switch (f.core.aov) {
        case Aov::Direct:
        case Aov::Final:
        case Aov::Indirect:
        case Aov::LpvSlice:
        case Aov::RsmFlux:
        case Aov::Sky: {
            const float compensation = std::exp2(f.core.exposureCompensation);
            if (f.core.autoExposure) return {compensation, 0.0f, TONEMAP_ACES, 1};
            return {f.core.exposure * compensation, 0.0f, TONEMAP_ACES, 0};
        }
        case Aov::RsmDepth:
        case Aov::RsmNormal:
        case Aov::ShadowMap: return {1.0f, 0.0f, TONEMAP_LINEAR, 0};
        case Aov::GvSlice: return {1.0f, 0.0f, TONEMAP_LINEAR, 0};
        case Aov::Albedo:
        case Aov::Cascade: return {1.0f, 0.0f, TONEMAP_SRGB, 0};
        case Aov::Normal: return {0.5f, 0.5f, TONEMAP_LINEAR, 0};
        case Aov::Depth: return {1.0f / depthFar, 0.0f, TONEMAP_LINEAR, 0};
        case Aov::Shadow:
        case Aov::Transmittance: return {1.0f, 0.0f, TONEMAP_LINEAR, 0};
        case Aov::DsmLists: {
            const float* scale = f.board.get(names::kCountAovScale);
            return {scale ? *scale : 1.0f, 0.0f, TONEMAP_LINEAR, 0};
        }
        case Aov::Velocity: return {1.0f / 32.0f, 0.5f, TONEMAP_LINEAR, 0};  // +-16 pixels
    }
    return {};
}

LightingTechnique::SkyKey LightingTechnique::skyKey(const SkySettings& settings, const std::vector<Light>& lights) {
    SkyKey key{settings};
    for (const Light& l : lights)
        if (l.type == LightType::Directional) {
            key.hasSun = true;
            key.sunDirection = l.direction, key.sunColor = l.color, key.sunIntensity = l.intensity;
            break;
        }
    // Only the analytic sky follows the sun; a map only asks whether there is one (its clipping).
    if (settings.kind != SkyKind::Analytic) key.sunDirection = key.sunColor = {}, key.sunIntensity = 0;
    return key;
}

// The sky is made again only when what it is made from changes (a moving sun: every frame), and
// each new sky gets a new generation, so that what others cache of it restarts. Its GPU passes are
// added here, in the update, so that they come before the passes of every technique that reads it.
void LightingTechnique::update(const FrameContext& f) {
    refreshSky(f.lights);
    if (gpuSkyStale_) {
        if (analyticSky_) gpuSky_.set(*analyticSky_);
        else gpuSky_.set(sky_, f.slot);
    }
    gpuSkyStale_ = false;
    background_ = gpuSky_.addTo(f.graph);
}

void LightingTechnique::refreshSky(const std::vector<Light>& lights) {
    SkyKey key = skyKey(settings_.sky, lights);
    if (skyMade_ && key == skyKey_) return;
    std::vector<std::string> warnings;
    const bool analytic = settings_.sky.kind == SkyKind::Analytic;
    analyticSky_ = analytic ? makeAnalyticSky(settings_.sky, lights, warnings) : std::nullopt;
    sky_ = analytic ? Sky() : makeSky(settings_.sky, lights, warnings);
    if (!analytic && settings_.sky.sunIlluminance > 0.0f)
        warnings.push_back(lightingOptions().flagOf<LightingSettings>([](auto& s) -> auto& { return s.sky.sunIlluminance; }) +
                           " scales the analytic sky only: ignored");
    // A moving sun would repeat its warning every frame: each is said once.
    for (const std::string& w : warnings)
        if (std::find(warnings_.begin(), warnings_.end(), w) == warnings_.end()) warnings_.push_back(w);
    skyKey_ = std::move(key);
    skyMade_ = true;
    skyLight_.enabled = analyticSky_.has_value() || sky_.enabled();
    ++skyLight_.generation;
    gpuSkyStale_ = true;
}

void LightingTechnique::addPasses(const FrameContext& f) {
    const ImageHandle indirect = irradiance_.addTo(f.graph);
    f.graph.publish(names::kIrradiance, indirect ? indirect : f.graph.import(noIndirect_));
    if (!f.graph.has(names::kSkyIrradiance)) f.graph.publish(names::kSkyIrradiance, f.graph.import(noSky_));
    lighting_.addTo(f.graph, background_);
}

void LightingTechnique::addOutputPasses(const FrameContext& f) {
    debugView_.addTo(f.graph, f.core.aov, f.core.aovLayer);
    const gpu::TonemapPush params = tonemapParams(f);
    const bool autoExposure = params.autoExposure != 0;
    if (autoExposure && !wasAuto_) exposure_.restart();
    wasAuto_ = autoExposure;
    tonemap_.addTo(f.graph, params,
                   exposure_.addTo(f.graph, autoExposure, settings_.exposureLowPercentile,
                                   settings_.exposureHighPercentile));
}

}  // namespace penumbra
