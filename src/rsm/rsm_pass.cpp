#include "rsm/rsm_pass.h"

#include <glm/gtc/matrix_inverse.hpp>

#include "render/raster.h"

namespace penumbra {

RsmPass::RsmPass(vk::Allocator& alloc, SceneGpu& scene, const RsmSettings& settings)
    : alloc_(alloc), scene_(scene), settings_(settings) {
    vk::Context& ctx = alloc.context();
    std::vector<vk::Binding> bindings = SceneGpu::drawSetBindings();
    bindings.push_back({3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});  // lights
    bindings.push_back({4, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});  // RSM layer table
    layout_ = vk::DescriptorLayout(ctx, bindings);
    vk::GraphicsDesc d;
    d.vertexShader = "render/scene.vert";
    d.fragmentShader = "rsm/rsm.frag";
    d.colorFormats = {VK_FORMAT_R16G16_SNORM, VK_FORMAT_R16G16B16A16_SFLOAT};
    d.depthFormat = VK_FORMAT_D32_SFLOAT;
    d.vertexStride = SceneGpu::vertexStride();
    d.vertexAttributes = SceneGpu::vertexAttributes();
    d.dynamicCullMode = true;
    d.frontFace = SceneGpu::sceneFrontFace(false);
    pipeline_ = vk::Pipeline::graphics(ctx, d, {layout_.handle()}, sizeof(gpu::RsmDrawPush));
    setLayers({}, 0);
}

void RsmPass::setLayers(const std::vector<RsmLayerSource>& layers, uint32_t slot) {
    sources_ = layers;
    const uint32_t n = std::max<uint32_t>(1, uint32_t(layers.size()));
    const uint32_t r = settings_.resolution;
    const VkImageUsageFlags target = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    if (!depth_ || depth_.layers() != n) {
        depth_ = vk::Image(alloc_, {VK_FORMAT_D32_SFLOAT, r, r, n, target | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                    "rsm-depth", 1, true});
        normal_ = vk::Image(alloc_, {VK_FORMAT_R16G16_SNORM, r, r, n, target | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
                                     "rsm-normal", 1, true});
        flux_ = vk::Image(alloc_, {VK_FORMAT_R16G16B16A16_SFLOAT, r, r, n,
                                   target | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, "rsm-flux", 1, true});
        layerTable_ = vk::BufferRing(alloc_, sizeof(gpu::GpuRsmLayer) * n, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                     "rsm-layers");
    }
    layerTable_.select(slot);
    std::vector<gpu::GpuRsmLayer> table(n);
    for (size_t i = 0; i < layers.size(); ++i) {
        const RsmLayerSource& s = layers[i];
        // The projection's texel size is for the shadow map; RSM texels are larger by the ratio.
        const float texel = s.projection.texelSize * float(s.shadowResolution) / float(r);
        table[i] = {s.projection.viewProj, glm::inverse(s.projection.viewProj),
                    {texel, s.projection.perspective ? 1.0f : 0.0f, float(s.light), 0.0f},
                    {float(s.cascade), s.lastCascade ? 1.0f : 0.0f, s.radiusScale, 0.0f}};
    }
    layerTable_.write(table.data(), table.size() * sizeof(gpu::GpuRsmLayer));
}

void RsmPass::addTo(FrameGraph& graph) {
    const ImageHandle depth = graph.import(depth_), normal = graph.import(normal_), flux = graph.import(flux_);
    const BufferHandle table = graph.import(layerTable_.current());
    graph.publish("rsm.depth", depth);
    graph.publish("rsm.normal", normal);
    graph.publish("rsm.flux", flux);
    graph.publish("rsm.layers", table);
    if (sources_.empty()) return;
    PassBuilder pass = graph.pass("rsm.render", PassKind::Raster);
    pass.pipeline(pipeline_)
        .use(depth, Use::DepthAttachment)
        .use(normal, Use::ColorAttachment)
        .use(flux, Use::ColorAttachment);
    scene_.declareDrawSet(pass, graph.buffer("views"));
    pass.storageBuffer(3, graph.buffer("lights")).storageBuffer(4, table);
    pass.record([this](PassContext& c) {
        const uint32_t r = settings_.resolution;
        for (uint32_t layer = 0; layer < sources_.size(); ++layer) {
            RasterTarget target{{r, r}};
            target.colors = {{normal_.layerView(layer), {{0, 0, 0, 0}}}, {flux_.layerView(layer), {{0, 0, 0, 0}}}};
            target.depth = depth_.layerView(layer);
            beginRaster(c.cmd, target);
            const RsmLayerSource& s = sources_[layer];
            scene_.draw(
                c.cmd,
                [&](const Draw& d) { pipeline_.push(c.cmd, gpu::RsmDrawPush{s.viewIndex, d.material, s.light, layer}); },
                [](const Material&) { return true; });
            vkCmdEndRendering(c.cmd);
        }
    });
}

}  // namespace penumbra
