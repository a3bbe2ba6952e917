#include "render/renderer.h"

#include <algorithm>

#include <fmt/format.h>

namespace penumbra {
namespace {

gpu::GpuLight toGpu(const Light& l, int layer, const LightProjection* proj, float normalOffset) {
    gpu::GpuLight g{};
    g.position = glm::vec4(l.position, float(static_cast<uint32_t>(l.type)));
    g.direction = glm::vec4(glm::normalize(l.direction), l.range);
    g.radiance = glm::vec4(l.color * l.intensity, layer >= 0 ? float(layer) : float(NO_SHADOW));
    g.spot = {std::cos(l.innerConeAngle), std::cos(l.outerConeAngle), normalOffset,
              proj && proj->perspective ? 1.0f : 0.0f};
    g.shadow = {proj ? proj->texelSize : 0.0f, 0, 0, 0};
    g.shadowViewProj = proj ? proj->viewProj : glm::mat4(1.0f);
    return g;
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

    std::vector<std::string> unshadowed;
    shadow_->assign(scene.lights, shadowLayerOfLight_, projections_, unshadowed);
    for (const std::string& name : unshadowed)
        warnings_.push_back(fmt::format("{} is lit without shadows (point-light shadows are not implemented yet)",
                                        name));
    const size_t lightCount = std::max<size_t>(scene.lights.size(), 1);
    setupGi();
    frame_ = vk::Buffer(alloc_, sizeof(gpu::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true, "frame");
    views_ = vk::Buffer(alloc_, sizeof(glm::mat4) * (1 + projections_.size()), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
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
    if (settings_.gi != GiMode::Rsm) return;
    rsm_ = std::make_unique<RsmPass>(alloc_, *sceneGpu_, settings_.rsm);
    rsmGather_ = std::make_unique<RsmGather>(alloc_, cmd_, settings_.width, settings_.height, settings_.rsm);
    // One RSM layer per shadow layer: the RSM is the shadow pass's light view with more targets.
    std::vector<RsmLayerSource> layers;
    for (size_t light = 0; light < scene_.lights.size(); ++light) {
        const int layer = shadowLayerOfLight_[light];
        if (layer >= 0)
            layers.push_back({uint32_t(light), uint32_t(1 + layer), projections_[layer], settings_.shadow.resolution});
    }
    if (layers.empty()) warnings_.push_back("--gi rsm: no directional or spot light casts shadows; no indirect light");
    rsm_->setLayers(layers);
}

void Renderer::updateBuffers(const Camera& camera) {
    const float aspect = float(settings_.width) / float(settings_.height);
    zfar_ = sceneFar(camera, scene_.bounds);
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
    for (const LightProjection& p : projections_) views.push_back(p.viewProj);
    views_.write(views.data(), views.size() * sizeof(glm::mat4));

    std::vector<gpu::GpuLight> lights;
    for (size_t i = 0; i < scene_.lights.size(); ++i) {
        int layer = shadowLayerOfLight_[i];
        lights.push_back(toGpu(scene_.lights[i], layer, layer >= 0 ? &projections_[layer] : nullptr,
                               settings_.shadow.normalOffset));
    }
    if (!lights.empty()) lights_.write(lights.data(), lights.size() * sizeof(gpu::GpuLight));
}

gpu::TonemapPush Renderer::tonemapParams(float zfar) const {
    switch (settings_.aov) {
        case Aov::Direct:
        case Aov::Final:
        case Aov::Indirect: return {{settings_.exposure, 0.0f, float(TONEMAP_ACES), 0.0f}};
        case Aov::Albedo: return {{1.0f, 0.0f, float(TONEMAP_SRGB), 0.0f}};
        case Aov::Normal: return {{0.5f, 0.5f, float(TONEMAP_LINEAR), 0.0f}};
        case Aov::Depth: return {{1.0f / zfar, 0.0f, float(TONEMAP_LINEAR), 0.0f}};
        case Aov::Shadow: return {{1.0f, 0.0f, float(TONEMAP_LINEAR), 0.0f}};
    }
    return {};
}

void Renderer::render(const Camera& camera) {
    updateBuffers(camera);
    graph_.clear();
    if (!projections_.empty()) shadow_->addTo(graph_, views_, 1, uint32_t(projections_.size()));
    gbuffer_->addTo(graph_, views_);
    if (rsm_) {
        rsm_->addTo(graph_, views_, lights_);
        rsmGather_->addTo(graph_, frame_, *gbuffer_, *rsm_);
    }
    vk::Image& indirect = rsmGather_ ? rsmGather_->irradiance() : noIndirect_;
    lighting_->addTo(graph_, frame_, lights_, *gbuffer_, shadow_->shadowMap(), indirect);
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
