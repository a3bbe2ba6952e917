#include "dsm/hair_passes.h"

#include <stdexcept>

#include "core/raster.h"
#include "dsm/bindings.h"

namespace penumbra {
namespace {

// Set 0 of the ribbon passes that only draw: the views and the hair buffers.
vk::DescriptorLayout ribbonLayout(vk::Context& ctx) {
    std::vector<vk::Binding> b{{HAIR_VIEWS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
    for (const vk::Binding& h : HairGpu::bindings()) b.push_back(h);
    return vk::DescriptorLayout(ctx, b);
}

void declareRibbonSet(PassBuilder& pass, const HairGpu& hair) {
    pass.storageBuffer(HAIR_VIEWS, pass.graph().buffer("views"));
    hair.declare(pass);
}

gpu::RibbonDrawPush ribbonPush(uint32_t viewRow, const RibbonView& v) { return {viewRow, 0, 0, 0, v}; }

}  // namespace

HairGBufferPass::HairGBufferPass(vk::Allocator& alloc, const HairGpu& hair)
    : alloc_(alloc), hair_(hair), layout_(ribbonLayout(alloc.context())) {}

// The pipeline takes the published G-buffer's formats (made with the first frame's targets).
void HairGBufferPass::makePipeline(const vk::Image& albedo, const vk::Image& normal, const vk::Image& depth) {
    vk::GraphicsDesc d = HairGpu::pipelineDesc("dsm/hair_gbuffer.frag");
    d.colorFormats = {albedo.format(), normal.format()};
    if (depth.format() != VK_FORMAT_D32_SFLOAT)  // GBufferPass was not told `rasterAfter`
        throw std::logic_error("hair.gbuffer: the camera's depth is not a depth image");
    d.depthFormat = depth.format();
    pipeline_ = vk::Pipeline::graphics(alloc_.context(), d, {layout_.handle()}, sizeof(gpu::RibbonDrawPush));
}

void HairGBufferPass::addTo(FrameGraph& graph, const RibbonView& camera) {
    const ImageHandle a = graph.image("gbuffer.albedo"), n = graph.image("gbuffer.normal"),
                      d = graph.image("gbuffer.depth");
    if (pipeline_.handle() == VK_NULL_HANDLE) makePipeline(graph.imageOf(a), graph.imageOf(n), graph.imageOf(d));
    PassBuilder pass = graph.pass("hair.gbuffer", PassKind::Raster);
    pass.pipeline(pipeline_).use(a, Use::ColorAttachment).use(n, Use::ColorAttachment).use(d, Use::DepthAttachment);
    declareRibbonSet(pass, hair_);
    pass.record([this, a, n, d, camera](PassContext& c) {
        RasterTarget target{c.image(a).extent(), {{c.image(a).view(), {}}, {c.image(n).view(), {}}},
                            c.image(d).view()};
        target.load = true;
        beginRaster(c.cmd, target);
        hair_.draw(c.cmd, pipeline_, ribbonPush(0, camera));
        vkCmdEndRendering(c.cmd);
    });
}

HairShadowPass::HairShadowPass(vk::Allocator& alloc, const HairGpu& hair, float depthBiasConstant,
                               float depthBiasSlope)
    : alloc_(alloc), hair_(hair), biasConstant_(depthBiasConstant), biasSlope_(depthBiasSlope),
      layout_(ribbonLayout(alloc.context())) {
    vk::GraphicsDesc d = HairGpu::pipelineDesc("");
    d.depthFormat = VK_FORMAT_D32_SFLOAT;
    d.depthBias = true;
    pipeline_ = vk::Pipeline::graphics(alloc.context(), d, {layout_.handle()}, sizeof(gpu::RibbonDrawPush));
}

void HairShadowPass::addTo(FrameGraph& graph, std::vector<HairShadowLayer> layers) {
    if (layers.empty()) return;
    const ImageHandle map = graph.image("shadow.map");
    if (graph.imageOf(map).format() != VK_FORMAT_D32_SFLOAT)  // ShadowMapPass::setHardwareCasters was not told
        throw std::logic_error("hair.shadow-map: the shadow map is not a depth image");
    PassBuilder pass = graph.pass("hair.shadow-map", PassKind::Raster);
    pass.pipeline(pipeline_).use(map, Use::DepthAttachment);
    declareRibbonSet(pass, hair_);
    pass.record([this, map, layers = std::move(layers)](PassContext& c) {
        vk::Image& image = c.image(map);
        for (const HairShadowLayer& l : layers) {
            RasterTarget target{image.extent(), {}, image.layerView(l.layer)};
            target.load = true;
            beginRaster(c.cmd, target);
            vkCmdSetDepthBias(c.cmd, biasConstant_, 0.0f, biasSlope_);
            hair_.draw(c.cmd, pipeline_, ribbonPush(l.viewRow, l.view));
            vkCmdEndRendering(c.cmd);
        }
    });
}

}  // namespace penumbra
