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
      useCompute_(computeRasterFor(settings.raster, alloc.context().properties())),
      moments_(alloc, settings.resolution),
      filter_(alloc) {
    assign({});
}

void ShadowMapPass::assign(const std::vector<Light>& lights) {
    lights_ = lights;
    layout_.assign(lights);
    const uint32_t layers = std::max<uint32_t>(uint32_t(layout_.layers().size()), 1u);
    const bool resized = !map_ || map_.layers() != layers;
    if (resized)
        map_ = vk::Image(alloc_, {VK_FORMAT_D32_SFLOAT, settings_.resolution, settings_.resolution, layers,
                                  VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                      VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                  "shadow-map", 1, true});
    if (useCompute_ && (resized || !compute_))
        compute_ = std::make_unique<ComputeRaster>(alloc_, scene_, settings_.resolution, layers);
    moments_.resize(layout_.momentLayerCount());
    // Host-visible tables, one copy per frame in flight, rewritten by update(); kept while their sizes hold.
    const size_t shadowed = std::max<size_t>(layout_.shadowed().size(), 1);
    if (layerTable_ && layerTable_.current().size() == sizeof(gpu::GpuShadowLayer) * layers &&
        lightTable_.current().size() == sizeof(gpu::GpuShadowLight) * shadowed)
        return;
    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    layerTable_ = vk::BufferRing(alloc_, sizeof(gpu::GpuShadowLayer) * layers, storage, "shadow-layers");
    lightTable_ = vk::BufferRing(alloc_, sizeof(gpu::GpuShadowLight) * std::max<size_t>(layout_.shadowed().size(), 1),
                                 storage, "shadow-lights");
    params_ = vk::BufferRing(alloc_, sizeof(gpu::GpuShadowParams), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, "shadow-params");
}

void ShadowMapPass::setFilters(const ShadowSettings& settings, const std::vector<Light>& lights) {
    setSettings(settings);
    assign(lights);
}

void ShadowMapPass::setSettings(const ShadowSettings& settings) {
    validate(settings);
    settings_ = settings;
    layout_.setSettings(settings);
    raster_.setSettings(settings);
}

void ShadowMapPass::update(const std::vector<Light>& lights, const Camera& camera, float aspect, float cameraFar,
                           uint32_t slot) {
    lights_ = lights;
    slot_ = slot;
    for (vk::BufferRing* ring : {&layerTable_, &lightTable_, &params_}) ring->select(slot);
    layout_.update(lights_, camera, aspect, cameraFar);
    const std::vector<gpu::GpuShadowLayer> layers = layout_.gpuLayers();
    const std::vector<gpu::GpuShadowLight> shadowed = layout_.gpuLights();
    const gpu::GpuShadowParams params = layout_.gpuParams(filter_.linearCompare());
    if (!layers.empty()) layerTable_.write(layers.data(), layers.size() * sizeof(layers[0]));
    if (!shadowed.empty()) lightTable_.write(shadowed.data(), shadowed.size() * sizeof(shadowed[0]));
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

void ShadowMapPass::addTo(FrameGraph& graph, uint32_t firstView,
                          const std::function<void(FrameGraph&)>& extraCasters) {
    const ImageHandle map = graph.import(map_);
    graph.publish("shadow.map", map);
    graph.publish("shadow.layers", graph.import(layerTable_.current()));
    graph.publish("shadow.lights", graph.import(lightTable_.current()));
    graph.publish("shadow.params", graph.import(params_.current()));
    if (!layers().empty()) {
        // The hardware pass clears every layer; with the compute rasterizer it draws only paraboloid lights.
        if (!compute_ || hasParaboloid()) {
            PassBuilder pass = graph.pass("shadow.map", PassKind::Raster);
            pass.pipeline(raster_.setLayoutPipeline()).use(map, Use::DepthAttachment);
            scene_.declareDrawSet(pass, graph.buffer("views"));
            const bool paraboloidOnly = compute_ != nullptr;
            pass.record([this, map, firstView, paraboloidOnly](PassContext& c) {
                raster_.record(c.cmd, c.image(map), firstView, layout_, paraboloidOnly);
            });
        }
        if (compute_) {
            compute_->setViews(computeViews(firstView), slot_);
            compute_->addTo(graph, "shadow.raster", map, graph.buffer("views"),
                            {settings_.depthBiasConstant, settings_.depthBiasSlope});
        }
        if (extraCasters) extraCasters(graph);
    }
    moments_.addTo(graph);
}

bool ShadowMapPass::hasParaboloid() const {
    for (const ShadowedLight& s : layout_.shadowed())
        if (s.kind == SHADOW_KIND_PARABOLOID) return true;
    return false;
}

// Every layer of every light but paraboloid ones (their edges bend: hardware tessellation).
std::vector<RasterViews> ShadowMapPass::computeViews(uint32_t firstView) const {
    std::vector<RasterViews> views;
    for (const ShadowedLight& s : layout_.shadowed())
        if (s.kind != SHADOW_KIND_PARABOLOID)
            views.push_back({firstView + s.firstLayer, s.firstLayer, s.layerCount, !raster_.drawsBlended(s.light)});
    return views;
}

void ShadowMapPass::addFilterTo(FrameGraph& graph) { filter_.addTo(graph, uint32_t(layout_.shadowed().size())); }

}  // namespace penumbra
