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
    setLayers({});
}

void RsmPass::setLayers(const std::vector<RsmLayerSource>& layers) {
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
        layerTable_ = vk::Buffer(alloc_, sizeof(gpu::GpuRsmLayer) * n, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true,
                                 "rsm-layers");
    }
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

void RsmPass::addTo(FrameGraph& graph, const vk::Buffer& views, const vk::Buffer& lights) {
    if (sources_.empty()) return;
    PassDesc pass;
    pass.name = "rsm.render";
    pass.kind = PassKind::Raster;
    pass.images = {{&depth_, Use::DepthAttachment},
                   {&normal_, Use::ColorAttachment},
                   {&flux_, Use::ColorAttachment},
                   {&scene_.textures(), Use::Sampled}};
    pass.buffers = {{&views, Use::StorageRead}, {&scene_.materials(), Use::StorageRead},
                    {&lights, Use::StorageRead}, {&layerTable_, Use::StorageRead}};
    pass.record = [this, &views, &lights](VkCommandBuffer cmd) {
        const uint32_t r = settings_.resolution;
        for (uint32_t layer = 0; layer < sources_.size(); ++layer) {
            RasterTarget target{{r, r}};
            target.colors = {{normal_.layerView(layer), {{0, 0, 0, 0}}}, {flux_.layerView(layer), {{0, 0, 0, 0}}}};
            target.depth = depth_.layerView(layer);
            beginRaster(cmd, target);
            pipeline_.bind(cmd);
            vk::DescriptorWrites w = scene_.drawSetWrites(views);
            w.storageBuffer(3, lights).storageBuffer(4, layerTable_).push(alloc_.context(), cmd, pipeline_);
            const RsmLayerSource& s = sources_[layer];
            scene_.draw(
                cmd,
                [&](const Draw& d) { pipeline_.push(cmd, gpu::RsmDrawPush{s.viewIndex, d.material, s.light, layer}); },
                [](const Material&) { return true; });
            vkCmdEndRendering(cmd);
        }
    };
    graph.add(std::move(pass));
}

}  // namespace penumbra
