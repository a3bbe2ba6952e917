#include "shadow/shadow_moments.h"

namespace penumbra {
namespace {
constexpr uint32_t kGroup = 64, kLanes = 4;  // BLUR_GROUP, BLUR_LANES in shaders/shadow/blur.glsl
}

ShadowMoments::ShadowMoments(vk::Allocator& alloc, uint32_t resolution) : alloc_(alloc), resolution_(resolution) {
    vk::Context& ctx = alloc.context();
    rows_ = vk::ComputeKernel(ctx, "shadow/moments_x.comp",
                              {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                               VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                              0);
    columns_ = vk::ComputeKernel(ctx, "shadow/moments_y.comp",
                                 {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                                  VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                 0);
    nearest_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});
    resize(0);
}

void ShadowMoments::resize(uint32_t layers) {
    if (layers == layers_) return;
    layers_ = layers;
    const uint32_t res = layers ? resolution_ : 1;
    const uint32_t n = std::max(layers, 1u);
    const VkImageUsageFlags usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                    VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    moments_ = vk::Image(alloc_, {VK_FORMAT_R32G32B32A32_SFLOAT, res, res, n, usage, "shadow-moments", 1, true});
    rowMoments_ = layers ? vk::Image(alloc_, {VK_FORMAT_R32G32B32A32_SFLOAT, res, res, n, VK_IMAGE_USAGE_STORAGE_BIT,
                                             "shadow-moments-rows", 1, true})
                         : vk::Image();
}

void ShadowMoments::addTo(FrameGraph& graph, vk::Image& depthMap, const vk::Buffer& layerTable,
                          const vk::Buffer& params) {
    if (layers_ == 0) return;
    const uint32_t res = resolution_, shadowLayers = depthMap.layers();
    PassDesc rows;
    rows.name = "shadow.moments";
    rows.images = {{&depthMap, Use::Sampled}, {&rowMoments_, Use::StorageWrite}};
    rows.buffers = {{&layerTable, Use::StorageRead}, {&params, Use::Uniform}};
    rows.record = [this, &depthMap, &layerTable, &params, res, shadowLayers](VkCommandBuffer cmd) {
        rows_.pipeline.bind(cmd);
        vk::DescriptorWrites()
            .sampled(0, depthMap.view(), nearest_.handle(), VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL)
            .storageImage(1, rowMoments_.view())
            .storageBuffer(2, layerTable)
            .uniformBuffer(3, params)
            .push(alloc_.context(), cmd, rows_.pipeline);
        vkCmdDispatch(cmd, vk::divUp(res, kGroup), vk::divUp(res, kLanes), shadowLayers);
    };
    graph.add(std::move(rows));

    PassDesc columns;
    columns.name = "shadow.blur";
    columns.images = {{&rowMoments_, Use::StorageRead}, {&moments_, Use::StorageWrite}};
    columns.buffers = {{&layerTable, Use::StorageRead}, {&params, Use::Uniform}};
    columns.record = [this, &layerTable, &params, res, shadowLayers](VkCommandBuffer cmd) {
        columns_.pipeline.bind(cmd);
        vk::DescriptorWrites()
            .storageImage(0, rowMoments_.view())
            .storageImage(1, moments_.view())
            .storageBuffer(2, layerTable)
            .uniformBuffer(3, params)
            .push(alloc_.context(), cmd, columns_.pipeline);
        vkCmdDispatch(cmd, vk::divUp(res, kLanes), vk::divUp(res, kGroup), shadowLayers);
    };
    graph.add(std::move(columns));
}

}  // namespace penumbra
