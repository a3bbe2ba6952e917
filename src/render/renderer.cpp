#include "render/renderer.h"

#include <algorithm>

#include <fmt/format.h>

namespace penumbra {
namespace {

// The light without its shadow fields (ShadowMapPass::fillGpuLight adds them).
gpu::GpuLight toGpu(const Light& l) {
    gpu::GpuLight g{};
    g.position = glm::vec4(l.position, float(static_cast<uint32_t>(l.type)));
    g.direction = glm::vec4(glm::normalize(l.direction), l.range);
    g.radiance = glm::vec4(l.color * l.intensity, float(NO_SHADOW));
    g.spot = {std::cos(l.innerConeAngle), std::cos(l.outerConeAngle), 0.0f, 0.0f};
    g.shadowViewProj = glm::mat4(1.0f);
    return g;
}

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

// Far plane that encloses the whole scene from the eye.
float sceneFar(const Camera& c, const Bounds& b) {
    if (c.zfar > 0.0f) return c.zfar;
    float far = 1.0f;
    for (int i = 0; i < 8; ++i) {
        glm::vec3 corner{(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z};
        far = std::max(far, glm::length(corner - c.eye));
    }
    return far * 1.05f;
}

}  // namespace

Renderer::Renderer(vk::Context& ctx, const Scene& scene, const RenderSettings& settings)
    : ctx_(ctx), scene_(scene), settings_(settings), alloc_(ctx), cmd_(alloc_), timer_(ctx) {
    if (settings.width == 0 || settings.height == 0 || settings.width > 16384 || settings.height > 16384)
        throw vk::VulkanError(fmt::format("image size {}x{} is out of range (1..16384)", settings.width,
                                          settings.height));
    sceneGpu_ = std::make_unique<SceneGpu>(cmd_, scene);
    drawLayout_ = vk::DescriptorLayout(ctx, SceneGpu::drawSetBindings());
    shadow_ = std::make_unique<ShadowMapPass>(alloc_, *sceneGpu_, settings.shadow, drawLayout_.handle());
    gbuffer_ = std::make_unique<GBufferPass>(alloc_, *sceneGpu_, settings.width, settings.height,
                                             drawLayout_.handle());
    lighting_ = std::make_unique<LightingPass>(alloc_, settings.width, settings.height);
    tonemap_ = std::make_unique<TonemapPass>(alloc_, settings.width, settings.height);

    shadow_->assign(scene.lights);
    const size_t lightCount = std::max<size_t>(scene.lights.size(), 1);
    setupGi();
    setupHairAndDsm();
    frame_ = vk::Buffer(alloc_, sizeof(gpu::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true, "frame");
    views_ = vk::Buffer(alloc_, sizeof(glm::mat4) * (1 + shadow_->layers().size()), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                        true, "views");
    lights_ = vk::Buffer(alloc_, sizeof(gpu::GpuLight) * lightCount, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true,
                         "lights");
}

Renderer::~Renderer() { ctx_.waitIdle(); }

void Renderer::setupGi() {
    noIndirect_ = vk::Image(alloc_, {VK_FORMAT_R16G16B16A16_SFLOAT, 1, 1, 1,
                                     VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, "no-indirect"});
    const uint64_t zero = 0;
    cmd_.uploadImage(noIndirect_, &zero, sizeof(zero));
    if (settings_.gi == GiMode::None) return;
    // Both GI techniques start from the RSM; LPV renders it larger and down-samples it.
    RsmSettings rsmSettings = settings_.rsm;
    if (settings_.gi == GiMode::Lpv) {
        rsmSettings.resolution = settings_.lpv.rsmResolution;
        lpv_ = std::make_unique<LightPropagationVolume>(alloc_, settings_.width, settings_.height, settings_.lpv,
                                                        scene_.bounds);
    } else {
        rsmGather_ = std::make_unique<RsmGather>(alloc_, cmd_, settings_.width, settings_.height, settings_.rsm);
    }
    rsm_ = std::make_unique<RsmPass>(alloc_, *sceneGpu_, rsmSettings);
    // The layers' projections are set every frame (cascades follow the camera): see updateBuffers.
    const std::vector<RsmLayerSource> layers = rsmLayersOf(*shadow_, lpv_ != nullptr || !settings_.rsm.perCascade);
    if (layers.empty()) warnings_.push_back("GI: no directional or spot light casts shadows; no indirect light");
    rsm_->setLayers(layers);
}

// Hair (src/dsm) in the G-buffer and, for lights without a deep shadow map, as an opaque caster in
// the ordinary shadow map; blended meshes and hair of lights with one go to their DSM instead.
void Renderer::setupHairAndDsm() {
    if (!scene_.strands.empty()) hair_ = std::make_unique<HairGpu>(cmd_, scene_);
    dsm_ = std::make_unique<DeepShadowMaps>(alloc_, *sceneGpu_, hair_.get(), settings_.dsm, settings_.shadow.resolution,
                                            warnings_);
    std::vector<uint32_t> deep;
    for (uint32_t i = 0; i < scene_.lights.size(); ++i)
        if (dsm_->covers(i)) deep.push_back(i);
    shadow_->setDeepShadowLights(deep);
    if (!hair_) return;
    for (uint32_t i = 0; i < scene_.lights.size(); ++i)
        if (scene_.lights[i].type == LightType::Point && scene_.lights[i].castsShadow &&
            settings_.shadow.pointMode == PointShadowMode::Paraboloid) {
            warnings_.push_back("hair casts no shadow in paraboloid point-light maps (use --point-shadow cube)");
            break;
        }
    hairGBuffer_ = std::make_unique<HairGBufferPass>(alloc_, *hair_, *gbuffer_);
    hairShadow_ = std::make_unique<HairShadowPass>(alloc_, *hair_, settings_.shadow.depthBiasConstant,
                                                   settings_.shadow.depthBiasSlope);
    shadow_->setExtraCasters([this](FrameGraph& g, vk::Image& map) {
        hairShadow_->addTo(g, map, views_, hairShadowLayers());
    });
}

// The shadow layers hair is drawn into: those of lights without a DSM (paraboloid point-light maps
// bend edges, which the ribbon vertex shader does not: hair casts no shadow there).
std::vector<HairShadowLayer> Renderer::hairShadowLayers() const {
    std::vector<HairShadowLayer> out;
    for (uint32_t k = 0; k < shadow_->layers().size(); ++k) {
        const ShadowLayer& l = shadow_->layers()[k];
        if (l.projection.paraboloid || dsm_->covers(l.light)) continue;
        out.push_back({k, 1 + k, lightRibbonView(scene_.lights[l.light], l.projection)});
    }
    return out;
}

void Renderer::updateBuffers(const Camera& camera) {
    const float aspect = float(settings_.width) / float(settings_.height);
    zfar_ = sceneFar(camera, scene_.bounds);
    shadow_->update(camera, aspect, zfar_);
    if (rsm_) rsm_->setLayers(rsmLayersOf(*shadow_, lpv_ != nullptr || !settings_.rsm.perCascade));
    gpu::FrameUniforms f{};
    f.viewProj = cameraViewProj(camera, aspect, zfar_);
    f.invViewProj = glm::inverse(f.viewProj);
    f.cameraPos = glm::vec4(camera.eye, zfar_);
    f.size = {settings_.width, settings_.height, uint32_t(scene_.lights.size()), uint32_t(settings_.aov)};
    f.options = {rsm_ ? 1u : 0u, 0u, 0u, 0u};
    f.lens = {2.0f * std::tan(0.5f * camera.fovy) / float(settings_.height), 0.0f, 0.0f, 0.0f};
    frame_.write(&f, sizeof(f));
    frameConstants_ = f;

    std::vector<glm::mat4> views{f.viewProj};
    for (const ShadowLayer& l : shadow_->layers()) views.push_back(l.projection.viewProj);
    views_.write(views.data(), views.size() * sizeof(glm::mat4));

    std::vector<gpu::GpuLight> lights;
    for (uint32_t i = 0; i < scene_.lights.size(); ++i) {
        lights.push_back(toGpu(scene_.lights[i]));
        shadow_->fillGpuLight(i, lights.back());
    }
    if (!lights.empty()) lights_.write(lights.data(), lights.size() * sizeof(gpu::GpuLight));
}

gpu::TonemapPush Renderer::tonemapParams(float zfar) const {
    switch (settings_.aov) {
        case Aov::Direct:
        case Aov::Final:
        case Aov::Indirect:
        case Aov::LpvSlice: return {{settings_.exposure, 0.0f, float(TONEMAP_ACES), 0.0f}};
        case Aov::GvSlice: return {{1.0f, 0.0f, float(TONEMAP_LINEAR), 0.0f}};
        case Aov::Albedo:
        case Aov::Cascade: return {{1.0f, 0.0f, float(TONEMAP_SRGB), 0.0f}};
        case Aov::Normal: return {{0.5f, 0.5f, float(TONEMAP_LINEAR), 0.0f}};
        case Aov::Depth: return {{1.0f / zfar, 0.0f, float(TONEMAP_LINEAR), 0.0f}};
        case Aov::Shadow:
        case Aov::Transmittance: return {{1.0f, 0.0f, float(TONEMAP_LINEAR), 0.0f}};
        case Aov::DsmLists: return {{1.0f / float(settings_.dsm.maxList), 0.0f, float(TONEMAP_LINEAR), 0.0f}};
    }
    return {};
}

void Renderer::render(const Camera& camera) {
    updateBuffers(camera);
    graph_.clear();
    shadow_->addTo(graph_, views_, 1);
    gbuffer_->addTo(graph_, views_);
    if (hairGBuffer_)
        hairGBuffer_->addTo(graph_, *gbuffer_, views_, cameraRibbonView(camera.eye, frameConstants_.lens.x));
    shadow_->addFilterTo(graph_, frame_, lights_, *gbuffer_);
    if (rsm_) rsm_->addTo(graph_, views_, lights_);
    if (rsmGather_) rsmGather_->addTo(graph_, frame_, *gbuffer_, *rsm_);
    if (lpv_) {
        lpv_->update(camera.eye);
        lpv_->addTo(graph_, frame_, lights_, *gbuffer_, *rsm_);
    }
    vk::Image& indirect = rsmGather_ ? rsmGather_->irradiance() : lpv_ ? lpv_->irradiance() : noIndirect_;
    dsm_->addTo(graph_);
    lighting_->addTo(graph_, frame_, lights_, *gbuffer_, shadow_->mask(), indirect, *dsm_);
    tonemap_->addTo(graph_, lighting_->hdr, tonemapParams(zfar_));
    timer_.reset();
    cmd_.submitAndWait([&](VkCommandBuffer cmd) { graph_.execute(cmd, &timer_); });
    timings_ = timer_.results();
}

std::vector<float> Renderer::readHdr() {
    std::vector<uint8_t> bytes = cmd_.readImage(lighting_->hdr, 16);
    std::vector<float> out(bytes.size() / 4);
    std::memcpy(out.data(), bytes.data(), bytes.size());
    return out;
}

std::vector<uint8_t> Renderer::readLdr() { return cmd_.readImage(tonemap_->ldr, 4); }

}  // namespace penumbra
