#include "render/lighting_pass.h"

namespace penumbra {

LightingPass::LightingPass(vk::Allocator& alloc, uint32_t width, uint32_t height) : alloc_(alloc) {
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
                                         {11, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}});
    pipeline_ = vk::Pipeline::compute(ctx, "render/lighting.comp", {layout_.handle()}, 0);
    pointSampler_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});
}

void LightingPass::addTo(FrameGraph& graph, const vk::Buffer& frame, const vk::Buffer& lights, GBufferPass& g,
                         vk::Image& shadowMask, vk::Image& indirect, const DeepShadowMaps& dsm) {
    PassDesc pass;
    pass.name = "lighting";
    pass.kind = PassKind::Compute;
    pass.images = {{&g.albedo, Use::Sampled}, {&g.normal, Use::Sampled}, {&g.depth, Use::Sampled},
                   {&shadowMask, Use::Sampled}, {&indirect, Use::Sampled}, {&hdr, Use::StorageWrite}};
    pass.buffers = {{&frame, Use::Uniform}, {&lights, Use::StorageRead}};
    dsm.addLookupInputs(pass);
    pass.record = [this, &frame, &lights, &g, &shadowMask, &indirect, &dsm](VkCommandBuffer cmd) {
        pipeline_.bind(cmd);
        vk::DescriptorWrites writes;
        dsm.writeLookup(writes);
        writes
            .uniformBuffer(0, frame)
            .storageBuffer(1, lights)
            .sampled(2, g.albedo.view(), pointSampler_.handle())
            .sampled(3, g.normal.view(), pointSampler_.handle())
            .sampled(4, g.depth.view(), pointSampler_.handle(), VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL)
            .sampled(5, shadowMask.view(), pointSampler_.handle())
            .storageImage(6, hdr.view())
            .sampled(7, indirect.view(), pointSampler_.handle())
            .push(alloc_.context(), cmd, pipeline_);
        vkCmdDispatch(cmd, vk::divUp(hdr.width(), 8), vk::divUp(hdr.height(), 8), 1);
    };
    graph.add(std::move(pass));
}

TonemapPass::TonemapPass(vk::Allocator& alloc, uint32_t width, uint32_t height) : alloc_(alloc) {
    vk::Context& ctx = alloc.context();
    ldr = vk::Image(alloc, {VK_FORMAT_R8G8B8A8_UNORM, width, height, 1,
                            VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, "ldr"});
    layout_ = vk::DescriptorLayout(ctx, {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}});
    pipeline_ = vk::Pipeline::compute(ctx, "render/tonemap.comp", {layout_.handle()}, sizeof(gpu::TonemapPush));
}

void TonemapPass::addTo(FrameGraph& graph, vk::Image& hdr, const gpu::TonemapPush& params) {
    PassDesc pass;
    pass.name = "tonemap";
    pass.kind = PassKind::Compute;
    pass.images = {{&hdr, Use::StorageRead}, {&ldr, Use::StorageWrite}};
    pass.record = [this, &hdr, params](VkCommandBuffer cmd) {
        pipeline_.bind(cmd);
        vk::DescriptorWrites().storageImage(0, hdr.view()).storageImage(1, ldr.view())
            .push(alloc_.context(), cmd, pipeline_);
        pipeline_.push(cmd, params);
        vkCmdDispatch(cmd, vk::divUp(ldr.width(), 8), vk::divUp(ldr.height(), 8), 1);
    };
    graph.add(std::move(pass));
}

}  // namespace penumbra
