#include "shadow/shadow_map_pass.h"

namespace penumbra {
namespace {

// Settings built in code skip the CLI's range checks: check them before any image is sized by them.
const ShadowSettings& validated(const ShadowSettings& s) {
    validate(s);
    return s;
}

}  // namespace

ShadowMapPass::ShadowMapPass(vk::Allocator& alloc, SceneGpu& scene, const ShadowSettings& settings,
                             VkDescriptorSetLayout drawLayout)
    : alloc_(alloc),
      scene_(scene),
      settings_(validated(settings)),
      layout_(settings, scene.scene().bounds),
      raster_(alloc.context(), scene, settings, drawLayout),
      moments_(alloc, settings.resolution),
      filter_(alloc) {
    assign({});
}

void ShadowMapPass::assign(const std::vector<Light>& lights) {
    lights_ = lights;
    layout_.assign(lights);
    const uint32_t layers = std::max<uint32_t>(uint32_t(layout_.layers().size()), 1u);
    if (!map_ || map_.layers() != layers)
        map_ = vk::Image(alloc_, {VK_FORMAT_D32_SFLOAT, settings_.resolution, settings_.resolution, layers,
                                  VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                      VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                  "shadow-map", 1, true});
    moments_.resize(layout_.momentLayerCount());
    // Host-visible tables, rewritten by update() while the GPU is idle between frames.
    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    layerTable_ = vk::Buffer(alloc_, sizeof(gpu::GpuShadowLayer) * layers, storage, true, "shadow-layers");
    lightTable_ = vk::Buffer(alloc_, sizeof(gpu::GpuShadowLight) * std::max<size_t>(layout_.shadowed().size(), 1),
                             storage, true, "shadow-lights");
    params_ = vk::Buffer(alloc_, sizeof(gpu::GpuShadowParams), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true,
                         "shadow-params");
}

void ShadowMapPass::update(const Camera& camera, float aspect, float cameraFar) {
    layout_.update(lights_, camera, aspect, cameraFar);
    const std::vector<gpu::GpuShadowLayer> layers = layout_.gpuLayers();
    const std::vector<gpu::GpuShadowLight> lights = layout_.gpuLights();
    const gpu::GpuShadowParams params = layout_.gpuParams(filter_.linearCompare());
    if (!layers.empty()) layerTable_.write(layers.data(), layers.size() * sizeof(layers[0]));
    if (!lights.empty()) lightTable_.write(lights.data(), lights.size() * sizeof(lights[0]));
    params_.write(&params, sizeof(params));
}

void ShadowMapPass::fillGpuLight(uint32_t light, gpu::GpuLight& g) const {
    const int index = layout_.shadowIndexOf(light);
    g.radiance.w = index >= 0 ? float(index) : float(NO_SHADOW);
    if (index < 0) return;
    const LightProjection& p = layers()[layout_.shadowed()[index].firstLayer].projection;
    g.spot.z = settings_.normalOffset;
    g.spot.w = p.perspective ? 1.0f : 0.0f;
    g.shadow = {p.texelSize, 0.0f, 0.0f, 0.0f};
    g.shadowViewProj = p.viewProj;
}

void ShadowMapPass::addTo(FrameGraph& graph, const vk::Buffer& views, uint32_t firstView) {
    if (layers().empty()) return;
    PassDesc pass;
    pass.name = "shadow.map";
    pass.kind = PassKind::Raster;
    pass.images = {{&map_, Use::DepthAttachment}, {&scene_.textures(), Use::Sampled}};
    pass.buffers = {{&views, Use::StorageRead}, {&scene_.materials(), Use::StorageRead}};
    pass.record = [this, &views, firstView](VkCommandBuffer cmd) { raster_.record(cmd, map_, views, firstView, layout_); };
    graph.add(std::move(pass));
    if (extraCasters_) extraCasters_(graph, map_);
    moments_.addTo(graph, map_, layerTable_, params_);
}

void ShadowMapPass::addFilterTo(FrameGraph& graph, const vk::Buffer& frame, const vk::Buffer& lights,
                                GBufferPass& gbuffer) {
    filter_.addTo(graph, frame, lights, gbuffer, {&map_, &moments(), &layerTable_, &lightTable_, &params_},
                  uint32_t(layout_.shadowed().size()));
}

}  // namespace penumbra
