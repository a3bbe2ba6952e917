#include "renderer/frame_techniques.h"
#include <algorithm>

#include "raster/raster_mode.h"

namespace penumbra {
namespace {

// RSM layers from the shadow layers: the RSM is the shadow pass's light view with more targets.
// LPV injection and, by default, the RSM gather take only each sun's last, widest cascade: cascades
// see the same surfaces, and a fine one lacks the distant VPLs (RsmSettings::perCascade); with
// perCascade the gather takes every cascade and picks one per receiver, as the seed does.
// Paraboloid layers have no matrix projection to rasterize with.
std::vector<RsmLayerSource> rsmLayersOf(const ShadowMapPass& shadow, bool widestCascadeOnly) {
    std::vector<RsmLayerSource> layers;
    const uint32_t res = shadow.settings().resolution;
    for (const ShadowedLight& sl : shadow.layout().shadowed()) {
        const bool cascades = sl.kind == SHADOW_KIND_CASCADES;
        for (uint32_t k = 0; k < sl.layerCount; ++k) {
            const uint32_t index = sl.firstLayer + k;
            const ShadowLayer& l = shadow.layers()[index];
            const bool last = k + 1 == sl.layerCount;
            if (l.projection.paraboloid || (cascades && widestCascadeOnly && !last)) continue;
            RsmLayerSource src{l.light, 1 + index, l.projection, res};
            if (cascades && !widestCascadeOnly) {
                src.cascade = k + 1;
                src.lastCascade = last;
                src.radiusScale = shadow.layers()[sl.firstLayer].projection.texelSize / l.projection.texelSize;
            }
            layers.push_back(src);
        }
    }
    return layers;
}

}  // namespace

CameraTechnique::CameraTechnique(vk::Allocator& alloc, GpuScene& scene, const RenderSettings& s,
                                 VkDescriptorSetLayout drawLayout)
    : gbuffer_(alloc, scene.meshes(), s.width, s.height, drawLayout, s.cameraPath, !s.translucency,
               computeRasterFor(s.shadow.raster, alloc.context().properties()),
               !s.translucency && scene.hair()) {  // HairGBufferPass below draws into the depth
    if (s.translucency) {
        translucency_ = std::make_unique<CameraTranslucency>(alloc, scene.meshes(), scene.hair(), s.width, s.height,
                                                             computeRasterFor(s.shadow.raster, alloc.context().properties()));
        if (!translucency_->active()) translucency_.reset();
    } else if (scene.hair()) {
        hair_ = std::make_unique<HairGBufferPass>(alloc, *scene.hair(), gbuffer_);
    }
}

void CameraTechnique::addPasses(const FrameContext& f) {
    gbuffer_.addTo(f.graph, f.slot);
    const RibbonView view = cameraRibbonView(f.camera.eye, f.uniforms.lens.x);
    if (hair_) hair_->addTo(f.graph, view);
    if (translucency_) translucency_->addBuildTo(f.graph, view, f.uniforms.viewProj);
}

// Hair (src/dsm) is an opaque caster in the ordinary shadow map of lights without a deep shadow
// map; blended meshes and hair of lights with one go to their DSM instead.
ShadowTechnique::ShadowTechnique(vk::Allocator& alloc, GpuScene& scene, const RenderSettings& s,
                                 VkDescriptorSetLayout drawLayout, const std::vector<Light>& lights,
                                 std::function<bool(uint32_t)> coveredByDsm, std::vector<std::string>& warnings)
    : pass_(alloc, scene.meshes(), s.shadow, drawLayout), coveredByDsm_(std::move(coveredByDsm)),
      hairGpu_(scene.hair()) {
    bool hairCasts = false;  // hair is rasterized into the map of a shadowed light without a DSM
    for (uint32_t i = 0; i < lights.size() && hairGpu_; ++i) hairCasts |= lights[i].castsShadow && !coveredByDsm_(i);
    pass_.setHardwareCasters(hairCasts);
    pass_.assign(lights);
    std::vector<uint32_t> deep;
    for (uint32_t i = 0; i < lights.size(); ++i)
        if (coveredByDsm_(i)) deep.push_back(i);
    pass_.setDeepShadowLights(deep);
    if (!hairGpu_) return;
    for (const Light& l : lights)
        if (l.type == LightType::Point && l.castsShadow && s.shadow.pointMode == PointShadowMode::Paraboloid) {
            warnings.push_back("hair casts no shadow in paraboloid point-light maps (use --point-shadow cube)");
            break;
        }
    hair_ = std::make_unique<HairShadowPass>(alloc, *hairGpu_, s.shadow.depthBiasConstant, s.shadow.depthBiasSlope);
}

void ShadowTechnique::applyPerFrame(const RenderSettings& s) {
    pass_.setSettings(s.shadow);
    if (hair_) hair_->setBias(s.shadow.depthBiasConstant, s.shadow.depthBiasSlope);
}

// The sun's cascades move in whole blocks of the texels that GI reads as one (an RSM texel, or one of
// LPV's down-sampled VPLs), so that those blocks stay on a world-fixed lattice as the camera moves:
// otherwise the RSM's texel centres crawl by fractions of a texel and its light flickers.
static uint32_t cascadeSnapTexels(const RenderSettings& s) {
    uint32_t giTexels = 0;
    if (s.gi == GiMode::Rsm) giTexels = s.rsm.resolution;
    if (s.gi == GiMode::Lpv) giTexels = s.lpv.vplResolution;
    return giTexels == 0 ? 1u : std::max(1u, s.shadow.resolution / giTexels);
}

void ShadowTechnique::update(const FrameContext& f) {
    pass_.update(f.lights, f.camera, f.aspect, f.zfar, f.slot, cascadeSnapTexels(f.settings));
}

// The shadow layers hair is drawn into: those of lights without a DSM (paraboloid point-light maps
// bend edges, which the ribbon vertex shader does not: hair casts no shadow there).
std::vector<HairShadowLayer> ShadowTechnique::hairLayers(const std::vector<Light>& lights) const {
    std::vector<HairShadowLayer> out;
    for (uint32_t k = 0; k < pass_.layers().size(); ++k) {
        const ShadowLayer& l = pass_.layers()[k];
        if (l.projection.paraboloid || coveredByDsm_(l.light)) continue;
        out.push_back({k, 1 + k, lightRibbonView(lights[l.light], l.projection)});
    }
    return out;
}

void ShadowTechnique::addPasses(const FrameContext& f) {
    std::function<void(FrameGraph&)> hairCasters;
    if (hair_) hairCasters = [&](FrameGraph& g) { hair_->addTo(g, hairLayers(f.lights)); };
    pass_.addTo(f.graph, 1, hairCasters);
    pass_.addFilterTo(f.graph);
}

DsmTechnique::DsmTechnique(vk::Allocator& alloc, GpuScene& scene, const RenderSettings& s,
                           const std::vector<Light>& lights, std::vector<std::string>& warnings)
    : maps_(alloc, scene.meshes(), scene.hair(), s.dsm, s.shadow.resolution, lights, warnings,
            computeRasterFor(s.shadow.raster, alloc.context().properties())),
      bounds_(scene.scene().bounds) {}

RsmTechnique::RsmTechnique(vk::Allocator& alloc, vk::CommandContext& cmd, GpuScene& scene, const RenderSettings& s,
                           ShadowMapPass& shadow, bool gather)
    : shadow_(shadow),
      widestCascadeOnly_(!gather || !s.rsm.perCascade),
      pass_(alloc, scene.meshes(), [&] {
          // LPV renders the RSM larger and down-samples it.
          RsmSettings r = s.rsm;
          if (!gather) r.resolution = s.lpv.rsmResolution;
          return r;
      }(), s.shadow.resolution) {
    if (gather) gather_ = std::make_unique<RsmGather>(alloc, cmd, s.width, s.height, s.rsm);
    if (gather && s.rsm.far == RsmFar::Flux)
        flux_ = std::make_unique<RsmFluxSampler>(alloc, s.rsm.resolution, s.rsm.seed);
    // The occupancy volume: the RSM gather's visibility, or what blocks LPV's propagation.
    if ((gather && s.rsm.visibility == RsmVisibility::Voxels) ||
        (!gather && s.lpv.geometry == LpvGeometry::Voxels))
        occupancy_ = std::make_unique<OccupancyVolume>(alloc, scene.meshes(), s.rsm.voxelResolution);
}

// The layers' projections change every frame (cascades follow the camera).
// The shadow pass draws these layers with visibility IDs, which the RSM is resolved from.
void RsmTechnique::update(const FrameContext& f) {
    pass_.setLayers(rsmLayersOf(shadow_, widestCascadeOnly_), f.slot);
    shadow_.requestIds(pass_.shadowLayers());
}

void RsmTechnique::addPasses(const FrameContext& f) {
    pass_.addTo(f.graph);
    if (flux_ && pass_.layerCount() > 0) flux_->addTo(f.graph, pass_.layerCount());
    if (occupancy_) occupancy_->addTo(f.graph);
    if (gather_) gather_->addTo(f.graph, pass_.layerCount(), f.slot);
}

void RsmTechnique::applyPerFrame(const RenderSettings& s) {
    if (gather_) gather_->setSettings(s.rsm);
    if (flux_) flux_->setSeed(s.rsm.seed);
}

LpvTechnique::LpvTechnique(vk::Allocator& alloc, const Bounds& bounds, const RenderSettings& s, RsmPass& rsm,
                           const OccupancyVolume* occupancy)
    : rsm_(rsm), occupancy_(occupancy), volume_(alloc, s.width, s.height, s.lpv, bounds) {}

void LpvTechnique::addPasses(const FrameContext& f) {
    volume_.update(f.camera.eye);
    volume_.addTo(f.graph, rsm_.layerCount(), occupancy_ ? occupancy_->generation() : 0);
}

LightingTechnique::LightingTechnique(vk::Allocator& alloc, vk::CommandContext& cmd, const RenderSettings& s,
                                     std::function<void(FrameGraph&)> afterLighting)
    : lighting_(alloc, s.width, s.height), afterLighting_(std::move(afterLighting)), debugView_(alloc.context()), tonemap_(alloc, s.width, s.height) {
    noIndirect_ = vk::Image(alloc, {VK_FORMAT_R16G16B16A16_SFLOAT, 1, 1, 1,
                                    VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, "no-indirect"});
    const uint64_t zero = 0;
    cmd.uploadImage(noIndirect_, &zero, sizeof(zero));
    noIds_ = vk::Image(alloc, {VK_FORMAT_R32_UINT, 1, 1, 1, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                               "no-ids"});
    cmd.uploadImage(noIds_, &zero, sizeof(uint32_t));
    if (s.giTemporal) history_ = std::make_unique<GiHistory>(alloc, s.width, s.height);
    historyAlpha_ = s.giTemporalAlpha;
}

gpu::TonemapPush LightingTechnique::tonemapParams(const RenderSettings& s, float depthFar) const {
    switch (s.aov) {
        case Aov::Direct:
        case Aov::Final:
        case Aov::Indirect:
        case Aov::LpvSlice:
        case Aov::RsmFlux: return {{s.exposure, 0.0f, float(TONEMAP_ACES), 0.0f}};
        case Aov::RsmDepth:
        case Aov::RsmNormal:
        case Aov::ShadowMap: return {{1.0f, 0.0f, float(TONEMAP_LINEAR), 0.0f}};
        case Aov::GvSlice: return {{1.0f, 0.0f, float(TONEMAP_LINEAR), 0.0f}};
        case Aov::Albedo:
        case Aov::Cascade: return {{1.0f, 0.0f, float(TONEMAP_SRGB), 0.0f}};
        case Aov::Normal: return {{0.5f, 0.5f, float(TONEMAP_LINEAR), 0.0f}};
        case Aov::Depth: return {{1.0f / depthFar, 0.0f, float(TONEMAP_LINEAR), 0.0f}};
        case Aov::Shadow:
        case Aov::Transmittance: return {{1.0f, 0.0f, float(TONEMAP_LINEAR), 0.0f}};
        case Aov::DsmLists: return {{1.0f / float(s.dsm.maxList), 0.0f, float(TONEMAP_LINEAR), 0.0f}};
        case Aov::Velocity: return {{1.0f / 32.0f, 0.5f, float(TONEMAP_LINEAR), 0.0f}};  // +-16 pixels
    }
    return {};
}

void LightingTechnique::addPasses(const FrameContext& f) {
    if (!f.graph.hasImage("gbuffer.ids")) f.graph.publish("gbuffer.ids", f.graph.import(noIds_));
    if (!f.graph.hasImage("gi.irradiance")) f.graph.publish("gi.irradiance", f.graph.import(noIndirect_));
    else if (history_) history_->addTo(f.graph, historyAlpha_);
    lighting_.addTo(f.graph);
    if (afterLighting_) afterLighting_(f.graph);
    debugView_.addTo(f.graph, f.settings.aov, f.settings.aovLayer);
    tonemap_.addTo(f.graph, tonemapParams(f.settings, f.sceneFar));
}

}  // namespace penumbra
