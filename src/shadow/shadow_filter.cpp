#include "shadow/shadow_filter.h"

#include "shadow/bindings.h"

namespace penumbra {

ShadowFilterPass::ShadowFilterPass(vk::Allocator& alloc) : alloc_(alloc) {
    vk::Context& ctx = alloc.context();
    const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    const VkDescriptorType uniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    kernel_ = vk::ComputeKernel(ctx, "shadow/filter.comp",
                                std::vector<vk::Binding>{{SHADOW_MASK_FRAME, uniform},
                                                         {SHADOW_MASK_LIGHTS, storage},
                                                         {SHADOW_MASK_GBUFFER_DEPTH, sampled},
                                                         {SHADOW_MASK_GBUFFER_NORMAL, sampled},
                                                         {SHADOW_MASK_DEPTH_MAP, sampled},
                                                         {SHADOW_MASK_MOMENTS, sampled},
                                                         {SHADOW_MASK_LAYERS, storage},
                                                         {SHADOW_MASK_SHADOW_LIGHTS, storage},
                                                         {SHADOW_MASK_PARAMS, uniform},
                                                         {SHADOW_MASK_OUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}},
                                0);
    point_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});
    // Outside a layer the border (depth 1) reads as lit: a point no layer covers casts and gets no shadow.
    depth_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER, false, false});
    moments_ = vk::Sampler(ctx, {VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});
}

void ShadowFilterPass::ensureMask(uint32_t width, uint32_t height, uint32_t layers) {
    if (mask_ && mask_.width() == width && mask_.height() == height && mask_.layers() == layers) return;
    mask_ = vk::Image(alloc_, {VK_FORMAT_R16G16_SFLOAT, width, height, layers,
                               VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                               "shadow-mask", 1, true});
}

void ShadowFilterPass::addTo(FrameGraph& graph, uint32_t shadowedLights) {
    const ImageHandle depth = graph.image("gbuffer.depth");
    const vk::Image& target = graph.imageOf(depth);
    ensureMask(target.width(), target.height(), std::max(shadowedLights, 1u));
    const ImageHandle mask = graph.import(mask_);
    graph.publish("shadow.mask", mask);
    if (shadowedLights == 0) return;  // the lighting pass reads no layer of the mask
    const ImageHandle map = graph.image("shadow.map");
    graph.pass("shadow.filter")
        .pipeline(kernel_.pipeline)
        .uniform(SHADOW_MASK_FRAME, graph.buffer("frame"))
        .storageBuffer(SHADOW_MASK_LIGHTS, graph.buffer("lights"))
        .sampled(SHADOW_MASK_GBUFFER_DEPTH, depth, point_.handle())
        .sampled(SHADOW_MASK_GBUFFER_NORMAL, graph.image("gbuffer.normal"), point_.handle())
        .sampled(SHADOW_MASK_DEPTH_MAP, map, depth_.handle())
        .sampled(SHADOW_MASK_MOMENTS, graph.image("shadow.moments"), moments_.handle())
        .storageBuffer(SHADOW_MASK_LAYERS, graph.buffer("shadow.layers"))
        .storageBuffer(SHADOW_MASK_SHADOW_LIGHTS, graph.buffer("shadow.lights"))
        .uniform(SHADOW_MASK_PARAMS, graph.buffer("shadow.params"))
        .storageImage(SHADOW_MASK_OUT, mask)
        .record([this](PassContext& c) {
            vkCmdDispatch(c.cmd, vk::divUp(mask_.width(), 8), vk::divUp(mask_.height(), 8), 1);
        });
}

}  // namespace penumbra
