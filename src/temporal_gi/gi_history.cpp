#include "temporal_gi/gi_history.h"

#include "shared/types.h"

namespace penumbra {

GiHistory::GiHistory(vk::Allocator& alloc, uint32_t width, uint32_t height) {
    vk::Context& ctx = alloc.context();
    constexpr VkDescriptorType kTex = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    constexpr VkDescriptorType kImg = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    constexpr VkDescriptorType kBuf = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    kernel_ = vk::ComputeKernel(ctx, "render/gi_history.comp",
                                {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kTex, kTex, kTex, kTex, kImg, kImg, kTex, kBuf, kBuf},
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
    const gpu::GiHistoryPush push{{alpha, valid_ ? 1.0f : 0.0f, 0.0f, 0.0f}};
    PassBuilder pass = graph.pass("gi.temporal");
    declarePreviousFrameInputs(pass, 7, nearest_.handle());
    pass.pipeline(kernel_.pipeline)
        .uniform(0, graph.buffer("frame"))
        .sampled(1, graph.image("gi.irradiance"), nearest_.handle())
        .sampled(2, graph.image("gbuffer.depth"), nearest_.handle())
        .sampled(3, graph.import(irradiance_[read]), nearest_.handle())
        .sampled(4, graph.import(depth_[read]), nearest_.handle())
        .storageImage(5, out)
        .storageImage(6, outDepth)
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
