#include "lighting/lighting_pass.h"

#include "core/previous_frame.h"
#include "lighting/lighting_bindings.h"

namespace penumbra {

LightingPass::LightingPass(vk::Allocator& alloc, uint32_t width, uint32_t height) {
    vk::Context& ctx = alloc.context();
    hdr = vk::Image(alloc, {kHdrFormat, width, height, 1,
                            VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, "hdr"});
    const VkDescriptorType ubo = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, ssbo = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                           tex = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, img = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    layout_ = vk::DescriptorLayout(
        ctx, {{LIGHTING_FRAME, ubo},          {LIGHTING_LIGHTS, ssbo},         {LIGHTING_GBUFFER_ALBEDO, tex},
              {LIGHTING_GBUFFER_NORMAL, tex}, {LIGHTING_GBUFFER_DEPTH, tex},   {LIGHTING_SHADOW_MASK, tex},
              {LIGHTING_HDR, img},            {LIGHTING_INDIRECT, tex},        {LIGHTING_DSM_LIGHTS, ssbo},
              {LIGHTING_DSM_HEADS, ssbo},     {LIGHTING_DSM_NODES, ssbo},      {LIGHTING_DSM_SIDE, ssbo},
              {LIGHTING_PROBE, ssbo},         {LIGHTING_MOTION_FIRST, tex},    {LIGHTING_MOTION_FIRST + 1, ssbo},
              {LIGHTING_MOTION_FIRST + 2, ssbo}, {LIGHTING_BACKGROUND_SKY, tex},
              {LIGHTING_SKY_IRRADIANCE, tex}});
    pipeline_ = vk::Pipeline::compute(ctx, "lighting/lighting.comp", {layout_.handle()}, 0);
    pointSampler_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});
}

void LightingPass::addTo(FrameGraph& graph, ImageHandle sky) {
    const ImageHandle out = graph.import(hdr);
    graph.publish("hdr", out);
    const VkSampler point = pointSampler_.handle();
    PassBuilder pass = graph.pass("lighting");
    declarePreviousFrameInputs(pass, LIGHTING_MOTION_FIRST, point);  // the velocity AOV
    pass.pipeline(pipeline_)
        .uniform(LIGHTING_FRAME, graph.buffer("frame"))
        .storageBuffer(LIGHTING_LIGHTS, graph.buffer("lights"))
        .sampled(LIGHTING_GBUFFER_ALBEDO, graph.image("gbuffer.albedo"), point)
        .sampled(LIGHTING_GBUFFER_NORMAL, graph.image("gbuffer.normal"), point)
        .sampled(LIGHTING_GBUFFER_DEPTH, graph.image("gbuffer.depth"), point)
        .sampled(LIGHTING_SHADOW_MASK, graph.image("shadow.mask"), point)
        .storageImage(LIGHTING_HDR, out)
        .sampled(LIGHTING_INDIRECT, graph.image("gi.irradiance"), point)
        .sampled(LIGHTING_SKY_IRRADIANCE, graph.image("sky.irradiance"), point)
        .storageBuffer(LIGHTING_DSM_LIGHTS, graph.buffer("dsm.lights"))
        .storageBuffer(LIGHTING_DSM_HEADS, graph.buffer("dsm.heads"))
        .storageBuffer(LIGHTING_DSM_NODES, graph.buffer("dsm.nodes"))
        .storageBuffer(LIGHTING_DSM_SIDE, graph.buffer("dsm.side"))
        .storageBuffer(LIGHTING_PROBE, graph.buffer("probe"), Use::StorageWrite)
        .sampled(LIGHTING_BACKGROUND_SKY, sky, point)
        .record([out](PassContext& c) {
            const vk::Image& image = c.image(out);
            vkCmdDispatch(c.cmd, vk::divUp(image.width(), 8), vk::divUp(image.height(), 8), 1);
        });
}

DebugViewPass::DebugViewPass(vk::Context& ctx)
    : kernel_(ctx, "lighting/debug_view.comp",
              {{DEBUG_VIEW_SOURCE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
               {DEBUG_VIEW_OUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}},
              sizeof(gpu::DebugViewPush)),
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
    const gpu::DebugViewPush push{uint32_t(aov), std::min(layer, last), 0, 0};
    graph.pass("debug-view")
        .pipeline(kernel_.pipeline)
        .sampled(DEBUG_VIEW_SOURCE, image, nearest_.handle())
        .storageImage(DEBUG_VIEW_OUT, out)
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
    layout_ = vk::DescriptorLayout(
        ctx, {{TONEMAP_HDR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, {TONEMAP_LDR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
              {TONEMAP_EXPOSURE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}});
    pipeline_ = vk::Pipeline::compute(ctx, "lighting/tonemap.comp", {layout_.handle()}, sizeof(gpu::TonemapPush));
}

void TonemapPass::addTo(FrameGraph& graph, const gpu::TonemapPush& params, BufferHandle exposure) {
    const ImageHandle out = graph.import(ldr);
    graph.publish("ldr", out);
    graph.pass("tonemap")
        .pipeline(pipeline_)
        .storageImage(TONEMAP_HDR, graph.image("hdr"), Use::StorageRead)
        .storageImage(TONEMAP_LDR, out)
        .storageBuffer(TONEMAP_EXPOSURE, exposure)
        .record([this, out, params](PassContext& c) {
            pipeline_.push(c.cmd, params);
            vkCmdDispatch(c.cmd, vk::divUp(ldr.width(), 8), vk::divUp(ldr.height(), 8), 1);
        });
}

}  // namespace penumbra
