#include "lighting/lighting_pass.h"

#include "core/previous_frame.h"

namespace penumbra {

LightingPass::LightingPass(vk::Allocator& alloc, uint32_t width, uint32_t height) {
    vk::Context& ctx = alloc.context();
    hdr = vk::Image(alloc, {VK_FORMAT_R32G32B32A32_SFLOAT, width, height, 1,
                            VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, "hdr"});
    layout_ = vk::DescriptorLayout(ctx, {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                         {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                         {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                         {3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                         {4, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                         {5, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                         {6, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                         {7, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                         {8, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                         {9, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                         {10, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                         {11, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                         {12, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                         {13, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                         {14, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                         {15, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}});
    pipeline_ = vk::Pipeline::compute(ctx, "render/lighting.comp", {layout_.handle()}, 0);
    pointSampler_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});
}

void LightingPass::addTo(FrameGraph& graph) {
    const ImageHandle out = graph.import(hdr);
    graph.publish("hdr", out);
    const VkSampler point = pointSampler_.handle();
    PassBuilder pass = graph.pass("lighting");
    declarePreviousFrameInputs(pass, 13, point);  // the velocity AOV
    pass.pipeline(pipeline_)
        .uniform(0, graph.buffer("frame"))
        .storageBuffer(1, graph.buffer("lights"))
        .sampled(2, graph.image("gbuffer.albedo"), point)
        .sampled(3, graph.image("gbuffer.normal"), point)
        .sampled(4, graph.image("gbuffer.depth"), point)
        .sampled(5, graph.image("shadow.mask"), point)
        .storageImage(6, out)
        .sampled(7, graph.image("gi.irradiance"), point)
        .storageBuffer(8, graph.buffer("dsm.lights"))
        .storageBuffer(9, graph.buffer("dsm.heads"))
        .storageBuffer(10, graph.buffer("dsm.nodes"))
        .storageBuffer(11, graph.buffer("dsm.side"))
        .storageBuffer(12, graph.buffer("probe"), Use::StorageWrite)
        .record([out](PassContext& c) {
            const vk::Image& image = c.image(out);
            vkCmdDispatch(c.cmd, vk::divUp(image.width(), 8), vk::divUp(image.height(), 8), 1);
        });
}

DebugViewPass::DebugViewPass(vk::Context& ctx)
    : kernel_(ctx, "render/debug_view.comp",
              {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, sizeof(gpu::DebugViewPush)),
      nearest_(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false}) {}

void DebugViewPass::addTo(FrameGraph& graph, Aov aov, uint32_t layer) {
    const char* source = aov == Aov::RsmDepth    ? "rsm.depth"
                         : aov == Aov::RsmNormal ? "rsm.normal"
                         : aov == Aov::RsmFlux   ? "rsm.flux"
                         : aov == Aov::ShadowMap ? "shadow.map"
                                                 : nullptr;
    if (!source || !graph.hasImage(source)) return;
    const ImageHandle image = graph.image(source), out = graph.image("hdr");
    const uint32_t last = graph.imageOf(image).layers() - 1;
    const gpu::DebugViewPush push{{uint32_t(aov), std::min(layer, last), 0, 0}};
    graph.pass("debug-view")
        .pipeline(kernel_.pipeline)
        .sampled(0, image, nearest_.handle())
        .storageImage(1, out)
        .record([this, out, push](PassContext& c) {
            kernel_.pipeline.push(c.cmd, push);
            const vk::Image& target = c.image(out);
            vkCmdDispatch(c.cmd, vk::divUp(target.width(), 8), vk::divUp(target.height(), 8), 1);
        });
}

TonemapPass::TonemapPass(vk::Allocator& alloc, uint32_t width, uint32_t height) {
    vk::Context& ctx = alloc.context();
    ldr = vk::Image(alloc, {VK_FORMAT_R8G8B8A8_UNORM, width, height, 1,
                            VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, "ldr"});
    layout_ = vk::DescriptorLayout(ctx, {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}});
    pipeline_ = vk::Pipeline::compute(ctx, "render/tonemap.comp", {layout_.handle()}, sizeof(gpu::TonemapPush));
}

void TonemapPass::addTo(FrameGraph& graph, const gpu::TonemapPush& params) {
    const ImageHandle out = graph.import(ldr);
    graph.publish("ldr", out);
    graph.pass("tonemap")
        .pipeline(pipeline_)
        .storageImage(0, graph.image("hdr"), Use::StorageRead)
        .storageImage(1, out)
        .record([this, out, params](PassContext& c) {
            pipeline_.push(c.cmd, params);
            vkCmdDispatch(c.cmd, vk::divUp(ldr.width(), 8), vk::divUp(ldr.height(), 8), 1);
        });
}

}  // namespace penumbra
