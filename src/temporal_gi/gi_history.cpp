#include "temporal_gi/gi_history.h"

#include "render/gi_history_bindings.h"
#include "shared/types.h"

namespace penumbra {

GiHistory::GiHistory(vk::Allocator& alloc, uint32_t width, uint32_t height) {
    vk::Context& ctx = alloc.context();
    constexpr VkDescriptorType kTex = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    constexpr VkDescriptorType kImg = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    constexpr VkDescriptorType kBuf = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    kernel_ = vk::ComputeKernel(ctx, "render/gi_history.comp",
                                {{GI_HISTORY_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                 {GI_HISTORY_CURRENT, kTex},
                                 {GI_HISTORY_GBUFFER_DEPTH, kTex},
                                 {GI_HISTORY_HISTORY, kTex},
                                 {GI_HISTORY_HISTORY_DEPTH, kTex},
                                 {GI_HISTORY_OUT, kImg},
                                 {GI_HISTORY_OUT_DEPTH, kImg},
                                 {GI_HISTORY_MOTION_FIRST, kTex},
                                 {GI_HISTORY_MOTION_FIRST + 1, kBuf},
                                 {GI_HISTORY_MOTION_FIRST + 2, kBuf}},
                                sizeof(gpu::GiHistoryPush));
    nearest_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});
    const VkImageUsageFlags usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    for (int i = 0; i < 2; ++i) {
        irradiance_[i] = vk::Image(alloc, {VK_FORMAT_R32G32B32A32_SFLOAT, width, height, 1, usage, "gi-history"});
        depth_[i] = vk::Image(alloc, {VK_FORMAT_R32_SFLOAT, width, height, 1, usage, "gi-history-depth"});
    }
}

void GiHistory::addTo(FrameGraph& graph, float alpha) {
    const uint32_t write = next_, read = 1 - next_;
    const ImageHandle out = graph.import(irradiance_[write]), outDepth = graph.import(depth_[write]);
    const gpu::GiHistoryPush push{alpha, valid_ ? 1u : 0u, 0, 0};
    PassBuilder pass = graph.pass("gi.temporal");
    declarePreviousFrameInputs(pass, GI_HISTORY_MOTION_FIRST, nearest_.handle());
    pass.pipeline(kernel_.pipeline)
        .uniform(GI_HISTORY_FRAME, graph.buffer("frame"))
        .sampled(GI_HISTORY_CURRENT, graph.image("gi.irradiance"), nearest_.handle())
        .sampled(GI_HISTORY_GBUFFER_DEPTH, graph.image("gbuffer.depth"), nearest_.handle())
        .sampled(GI_HISTORY_HISTORY, graph.import(irradiance_[read]), nearest_.handle())
        .sampled(GI_HISTORY_HISTORY_DEPTH, graph.import(depth_[read]), nearest_.handle())
        .storageImage(GI_HISTORY_OUT, out)
        .storageImage(GI_HISTORY_OUT_DEPTH, outDepth)
        .record([this, out, push](PassContext& c) {
            kernel_.pipeline.push(c.cmd, push);
            const vk::Image& image = c.image(out);
            vkCmdDispatch(c.cmd, vk::divUp(image.width(), 8), vk::divUp(image.height(), 8), 1);
        });
    graph.publish("gi.irradiance", out);
    next_ = read;
    valid_ = true;
}

}  // namespace penumbra
