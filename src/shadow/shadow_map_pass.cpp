#include "shadow/shadow_map_pass.h"

#include <algorithm>

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
      useCompute_(computeRasterFor(settings.raster, alloc.context().properties(), settings.resolution)),
      moments_(alloc, settings.resolution),
      filter_(alloc) {
    assign({});
}

void ShadowMapPass::assign(const std::vector<Light>& lights) {
    lights_ = lights;
    layout_.assign(lights);
    const uint32_t layers = std::max<uint32_t>(uint32_t(layout_.layers().size()), 1u);
    // The compute rasterizer writes an R32_SFLOAT map itself when it draws every layer: no copy into
    // a depth format (raster/tiles.glsl). A raster pass into the map needs D32_SFLOAT.
    const VkFormat format = useCompute_ && !hasParaboloid() && !hardwareCasters_ ? VK_FORMAT_R32_SFLOAT
                                                                                : VK_FORMAT_D32_SFLOAT;
    const bool resized = !map_ || map_.layers() != layers || map_.format() != format;
    invalidate();
    if (resized) {
        const VkImageUsageFlags target = format == VK_FORMAT_D32_SFLOAT ? VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT
                                                                        : VK_IMAGE_USAGE_STORAGE_BIT;
        map_ = vk::Image(alloc_, {format, settings_.resolution, settings_.resolution, layers,
                                  target | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                      VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                  "shadow-map", 1, true});
    }
    if (useCompute_ && (resized || !compute_))
        compute_ = makeDepthRaster(alloc_, scene_, VkExtent2D{settings_.resolution, settings_.resolution}, layers);
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
    if (settings.depthBiasConstant != settings_.depthBiasConstant || settings.depthBiasSlope != settings_.depthBiasSlope)
        invalidate();
    settings_ = settings;
    layout_.setSettings(settings);
    raster_.setSettings(settings);
}

void ShadowMapPass::update(const std::vector<Light>& lights, const Camera& camera, float aspect, float cameraFar,
                           uint32_t slot, uint32_t cascadeSnapTexels) {
    lights_ = lights;
    slot_ = slot;
    for (vk::BufferRing* ring : {&layerTable_, &lightTable_, &params_}) ring->select(slot);
    layout_.update(lights_, camera, aspect, cameraFar, cascadeSnapTexels);
    const std::vector<gpu::GpuShadowLayer> layers = layout_.gpuLayers();
    const std::vector<gpu::GpuShadowLight> shadowed = layout_.gpuLights();
    const gpu::GpuShadowParams params = layout_.gpuParams();
    if (!layers.empty()) layerTable_.write(layers.data(), layers.size() * sizeof(layers[0]));
    // A layer's depth depends on its projection only (the split distances only pick layers).
    const auto same = [](const gpu::GpuShadowLayer& a, const gpu::GpuShadowLayer& b) {
        return a.viewProj == b.viewProj && a.texelSize == b.texelSize && a.zNear == b.zNear && a.zFar == b.zFar &&
               a.discScale == b.discScale;
    };
    dirty_.assign(layers.size(), true);
    for (size_t k = 0; k < layers.size() && k < held_.size(); ++k) dirty_[k] = !same(layers[k], held_[k]);
    held_ = layers;
    if (!shadowed.empty()) lightTable_.write(shadowed.data(), shadowed.size() * sizeof(shadowed[0]));
    params_.write(&params, sizeof(params));
}

void ShadowMapPass::fillGpuLight(uint32_t light, gpu::GpuLight& g) const {
    const int index = layout_.shadowIndexOf(light);
    g.shadowIndex = index >= 0 ? index : NO_SHADOW;
    if (index < 0) return;
    const LightProjection& p = layers()[layout_.shadowed()[index].firstLayer].projection;
    g.normalOffset = settings_.normalOffset;
    g.perspective = p.perspective ? 1u : 0u;
    g.shadowTexelSize = p.texelSize;
    g.shadowViewProj = p.viewProj;
}

void ShadowMapPass::addTo(FrameGraph& graph, uint32_t firstView,
                          const std::function<void(FrameGraph&)>& extraCasters) {
    const ImageHandle map = graph.import(map_);
    graph.publish("shadow.map", map);
    layersDrawn_ = 0;
    if (dirty_.size() != layers().size()) dirty_.assign(layers().size(), true);  // no update() this frame
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
            std::vector<bool> draws = dirty_;
            for (uint32_t l : idLayers_) draws[l] = false;  // drawn with their IDs below
            for (size_t k = 0; k < draws.size(); ++k) {
                if (paraboloidOnly && !layers()[k].projection.paraboloid) draws[k] = false;
                layersDrawn_ += draws[k];
            }
            pass.record([this, map, firstView, paraboloidOnly, draws = std::move(draws)](PassContext& c) {
                raster_.record(c.cmd, c.image(map), firstView, layout_, paraboloidOnly,
                               [&](uint32_t layer) { return bool(draws[layer]); });
            });
        }
        if (compute_) {
            const ImageHandle ids = importIds(graph);  // first: a new ID image holds no layer
            const std::vector<RasterViews> views = computeViews(firstView);
            for (const RasterViews& v : views) layersDrawn_ += v.layerCount;
            heldIds_ = idLayers_;
            compute_->setViews(views, slot_);
            compute_->addTo(graph, "shadow.raster", map, graph.buffer("views"),
                            {settings_.depthBiasConstant, settings_.depthBiasSlope}, ids);
        } else {
            addIdPass(graph, map, firstView);
        }
        if (extraCasters) extraCasters(graph);
    }
    idLayers_.clear();
    moments_.addTo(graph);
}

// The ID image of this frame's requested layers ("shadow.ids"; none when no layer is requested).
ImageHandle ShadowMapPass::importIds(FrameGraph& graph) {
    if (idLayers_.empty()) return {};
    const uint32_t n = uint32_t(idLayers_.size());
    if (!ids_ || ids_.layers() != n) {
        heldIds_.clear();
        ids_ = vk::Image(alloc_, {VK_FORMAT_R32_UINT, settings_.resolution, settings_.resolution, n,
                                  VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                                      VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                  "shadow-ids", 1, true});
    }
    const ImageHandle ids = graph.import(ids_);
    graph.publish("shadow.ids", ids);
    return ids;
}

// The hardware draws the layers with an RSM once each, with depth and visibility IDs.
void ShadowMapPass::addIdPass(FrameGraph& graph, ImageHandle map, uint32_t firstView) {
    const ImageHandle ids = importIds(graph);
    if (!ids) return;
    const uint32_t n = uint32_t(idLayers_.size());
    PassBuilder pass = graph.pass("shadow.map-ids", PassKind::Raster);
    pass.pipeline(raster_.setLayoutPipeline()).use(map, Use::DepthAttachment).use(ids, Use::ColorAttachment);
    scene_.declareDrawSet(pass, graph.buffer("views"));
    std::vector<uint32_t> drawn;  // ID layers whose shadow layer changed, or that held another layer
    for (uint32_t i = 0; i < n; ++i)
        if (dirty_[idLayers_[i]] || heldIds_ != idLayers_) drawn.push_back(i);
    layersDrawn_ += uint32_t(drawn.size());
    heldIds_ = idLayers_;
    pass.record([this, map, ids, firstView, layers = idLayers_, drawn = std::move(drawn)](PassContext& c) {
        for (uint32_t i : drawn)
            raster_.recordIds(c.cmd, c.image(map), c.image(ids), layers[i], i, firstView + layers[i],
                              this->layers()[layers[i]].light);
    });
}

bool ShadowMapPass::hasParaboloid() const {
    for (const ShadowedLight& s : layout_.shadowed())
        if (s.kind == SHADOW_KIND_PARABOLOID) return true;
    return false;
}

// The layers of every light but paraboloid ones (their edges bend: hardware tessellation) that must
// be drawn this frame (their projection changed, or a layer with IDs that the ID image does not hold:
// the others keep what they hold, as the hardware pass's cached layers do), in runs of consecutive
// depth-only layers; a layer with IDs (an RSM's: directional and spot lights only) is a run of its own.
std::vector<RasterViews> ShadowMapPass::computeViews(uint32_t firstView) const {
    std::vector<RasterViews> views;
    for (const ShadowedLight& s : layout_.shadowed()) {
        if (s.kind == SHADOW_KIND_PARABOLOID) continue;
        const bool skipBlended = !raster_.drawsBlended(s.light);
        for (uint32_t k = 0; k < s.layerCount; ++k) {
            const uint32_t l = s.firstLayer + k;
            const auto id = std::find(idLayers_.begin(), idLayers_.end(), l);
            const uint32_t idLayer = id == idLayers_.end() ? RasterViews::kNoIds : uint32_t(id - idLayers_.begin());
            if (!dirty_[l] && (idLayer == RasterViews::kNoIds || heldIds_ == idLayers_)) continue;
            const bool extends = !views.empty() && views.back().firstLayer + views.back().layerCount == l &&
                                 views.back().skipBlended == skipBlended &&
                                 views.back().firstIdLayer == RasterViews::kNoIds;
            if (extends && idLayer == RasterViews::kNoIds)
                ++views.back().layerCount;
            else
                views.push_back({firstView + l, l, 1, skipBlended, idLayer});
        }
    }
    return views;
}

void ShadowMapPass::addFilterTo(FrameGraph& graph) { filter_.addTo(graph, uint32_t(layout_.shadowed().size())); }

}  // namespace penumbra
