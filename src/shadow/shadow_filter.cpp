#include "shadow/shadow_filter.h"

namespace penumbra {

ShadowFilterPass::ShadowFilterPass(vk::Allocator& alloc) : alloc_(alloc) {
    vk::Context& ctx = alloc.context();
    VkFormatProperties depth;
    vkGetPhysicalDeviceFormatProperties(ctx.physicalDevice(), VK_FORMAT_D32_SFLOAT, &depth);
    linearCompare_ = (depth.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) != 0;
    const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    kernel_ = vk::ComputeKernel(ctx, "shadow/filter.comp",
                                {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, storage, sampled, sampled, sampled, sampled,
                                 sampled, storage, storage, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                 VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                0);
    point_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});
    // Outside a layer the border (depth 1) reads as lit: a point no layer covers casts and gets no shadow.
    compare_ = vk::Sampler(ctx, {linearCompare_ ? VK_FILTER_LINEAR : VK_FILTER_NEAREST,
                                 VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER, true, false});
    depth_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER, false, false});
    moments_ = vk::Sampler(ctx, {VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});
}

void ShadowFilterPass::ensureMask(uint32_t width, uint32_t height, uint32_t layers) {
    if (mask_ && mask_.width() == width && mask_.height() == height && mask_.layers() == layers) return;
    mask_ = vk::Image(alloc_, {VK_FORMAT_R16G16_SFLOAT, width, height, layers,
                               VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                               "shadow-mask", 1, true});
}

void ShadowFilterPass::addTo(FrameGraph& graph, const vk::Buffer& frame, const vk::Buffer& lights, GBufferPass& g,
                             const ShadowFilterInputs& in, uint32_t shadowedLights) {
    ensureMask(g.depth.width(), g.depth.height(), std::max(shadowedLights, 1u));
    if (shadowedLights == 0) return;  // the lighting pass reads no layer of the mask
    PassDesc pass;
    pass.name = "shadow.filter";
    pass.images = {{&g.depth, Use::Sampled}, {&g.normal, Use::Sampled}, {in.depthMap, Use::Sampled},
                   {in.moments, Use::Sampled}, {&mask_, Use::StorageWrite}};
    pass.buffers = {{&frame, Use::Uniform}, {&lights, Use::StorageRead}, {in.layerTable, Use::StorageRead},
                    {in.lightTable, Use::StorageRead}, {in.params, Use::Uniform}};
    pass.record = [this, &frame, &lights, &g, in](VkCommandBuffer cmd) {
        const VkImageLayout depthRead = VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL;
        kernel_.pipeline.bind(cmd);
        vk::DescriptorWrites()
            .uniformBuffer(0, frame)
            .storageBuffer(1, lights)
            .sampled(2, g.depth.view(), point_.handle(), depthRead)
            .sampled(3, g.normal.view(), point_.handle())
            .sampled(4, in.depthMap->view(), compare_.handle(), depthRead)
            .sampled(5, in.depthMap->view(), depth_.handle(), depthRead)
            .sampled(6, in.moments->view(), moments_.handle())
            .storageBuffer(7, *in.layerTable)
            .storageBuffer(8, *in.lightTable)
            .uniformBuffer(9, *in.params)
            .storageImage(10, mask_.view())
            .push(alloc_.context(), cmd, kernel_.pipeline);
        vkCmdDispatch(cmd, vk::divUp(mask_.width(), 8), vk::divUp(mask_.height(), 8), 1);
    };
    graph.add(std::move(pass));
}

}  // namespace penumbra
