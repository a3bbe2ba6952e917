#include "dsm/hair_passes.h"

#include "render/raster.h"

namespace penumbra {
namespace {

// Set 0 of the ribbon passes that only draw: the views (binding 0) and the hair buffers (3, 4).
vk::DescriptorLayout ribbonLayout(vk::Context& ctx) {
    std::vector<vk::Binding> b{{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
    for (const vk::Binding& h : HairGpu::bindings()) b.push_back(h);
    return vk::DescriptorLayout(ctx, b);
}

void pushRibbonSet(vk::Context& ctx, VkCommandBuffer cmd, const vk::Pipeline& p, const vk::Buffer& views,
                   const HairGpu& hair) {
    vk::DescriptorWrites w;
    w.storageBuffer(0, views);
    hair.write(w);
    w.push(ctx, cmd, p);
}

gpu::HairDrawPush ribbonPush(uint32_t viewRow, const RibbonView& v) {
    return {{viewRow, 0, 0, 0}, v.viewer, v.footprint};
}

}  // namespace

HairGBufferPass::HairGBufferPass(vk::Allocator& alloc, const HairGpu& hair, const GBufferPass& g)
    : alloc_(alloc), hair_(hair), layout_(ribbonLayout(alloc.context())) {
    vk::GraphicsDesc d = HairGpu::pipelineDesc("dsm/hair_gbuffer.frag");
    d.colorFormats = {g.albedo.format(), g.normal.format()};
    d.depthFormat = g.depth.format();
    pipeline_ = vk::Pipeline::graphics(alloc.context(), d, {layout_.handle()}, sizeof(gpu::HairDrawPush));
}

void HairGBufferPass::addTo(FrameGraph& graph, GBufferPass& g, const vk::Buffer& views, const RibbonView& camera) {
    PassDesc pass;
    pass.name = "hair.gbuffer";
    pass.kind = PassKind::Raster;
    pass.images = {{&g.albedo, Use::ColorAttachment}, {&g.normal, Use::ColorAttachment},
                   {&g.depth, Use::DepthAttachment}};
    pass.buffers = {{&views, Use::StorageRead}, {&hair_.points(), Use::StorageRead},
                    {&hair_.strands(), Use::StorageRead}};
    pass.record = [this, &g, &views, camera](VkCommandBuffer cmd) {
        RasterTarget target{g.albedo.extent(), {{g.albedo.view(), {}}, {g.normal.view(), {}}}, g.depth.view()};
        target.load = true;
        beginRaster(cmd, target);
        pipeline_.bind(cmd);
        pushRibbonSet(alloc_.context(), cmd, pipeline_, views, hair_);
        hair_.draw(cmd, pipeline_, ribbonPush(0, camera));
        vkCmdEndRendering(cmd);
    };
    graph.add(std::move(pass));
}

HairShadowPass::HairShadowPass(vk::Allocator& alloc, const HairGpu& hair, float depthBiasConstant,
                               float depthBiasSlope)
    : alloc_(alloc), hair_(hair), biasConstant_(depthBiasConstant), biasSlope_(depthBiasSlope),
      layout_(ribbonLayout(alloc.context())) {
    vk::GraphicsDesc d = HairGpu::pipelineDesc("");
    d.depthFormat = VK_FORMAT_D32_SFLOAT;
    d.depthBias = true;
    pipeline_ = vk::Pipeline::graphics(alloc.context(), d, {layout_.handle()}, sizeof(gpu::HairDrawPush));
}

void HairShadowPass::addTo(FrameGraph& graph, vk::Image& map, const vk::Buffer& views,
                           std::vector<HairShadowLayer> layers) {
    if (layers.empty()) return;
    PassDesc pass;
    pass.name = "hair.shadow-map";
    pass.kind = PassKind::Raster;
    pass.images = {{&map, Use::DepthAttachment}};
    pass.buffers = {{&views, Use::StorageRead}, {&hair_.points(), Use::StorageRead},
                    {&hair_.strands(), Use::StorageRead}};
    pass.record = [this, &map, &views, layers = std::move(layers)](VkCommandBuffer cmd) {
        for (const HairShadowLayer& l : layers) {
            RasterTarget target{map.extent(), {}, map.layerView(l.layer)};
            target.load = true;
            beginRaster(cmd, target);
            vkCmdSetDepthBias(cmd, biasConstant_, 0.0f, biasSlope_);
            pipeline_.bind(cmd);
            pushRibbonSet(alloc_.context(), cmd, pipeline_, views, hair_);
            hair_.draw(cmd, pipeline_, ribbonPush(l.viewRow, l.view));
            vkCmdEndRendering(cmd);
        }
    };
    graph.add(std::move(pass));
}

}  // namespace penumbra
