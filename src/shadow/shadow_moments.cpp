#include "shadow/shadow_moments.h"

#include "shadow/bindings.h"

namespace penumbra {
namespace {
constexpr uint32_t kGroup = 64, kLanes = 4;  // BLUR_GROUP, BLUR_LANES in shaders/shadow/blur.glsl
}

ShadowMoments::ShadowMoments(vk::Allocator& alloc, uint32_t resolution) : alloc_(alloc), resolution_(resolution) {
    vk::Context& ctx = alloc.context();
    const VkDescriptorType image = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, buffer = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                           uniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    rows_ = vk::ComputeKernel(ctx, "shadow/moments_x.comp",
                              std::vector<vk::Binding>{{MOMENT_ROWS_DEPTH_MAP, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                                       {MOMENT_ROWS_OUT, image},
                                                       {MOMENT_ROWS_LAYERS, buffer},
                                                       {MOMENT_ROWS_PARAMS, uniform}},
                              0);
    columns_ = vk::ComputeKernel(ctx, "shadow/moments_y.comp",
                                 std::vector<vk::Binding>{{MOMENT_COLUMNS_ROWS, image},
                                                          {MOMENT_COLUMNS_OUT, image},
                                                          {MOMENT_COLUMNS_LAYERS, buffer},
                                                          {MOMENT_COLUMNS_PARAMS, uniform}},
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

void ShadowMoments::addTo(FrameGraph& graph) {
    const ImageHandle out = graph.import(moments_);
    graph.publish("shadow.moments", out);
    if (layers_ == 0) return;
    const ImageHandle depthMap = graph.image("shadow.map"), rows = graph.import(rowMoments_);
    const BufferHandle layerTable = graph.buffer("shadow.layers"), params = graph.buffer("shadow.params");
    const uint32_t res = resolution_, shadowLayers = graph.imageOf(depthMap).layers();
    graph.pass("shadow.moments")
        .pipeline(rows_.pipeline)
        .sampled(MOMENT_ROWS_DEPTH_MAP, depthMap, nearest_.handle())
        .storageImage(MOMENT_ROWS_OUT, rows)
        .storageBuffer(MOMENT_ROWS_LAYERS, layerTable)
        .uniform(MOMENT_ROWS_PARAMS, params)
        .record([res, shadowLayers](PassContext& c) {
            vkCmdDispatch(c.cmd, vk::divUp(res, kGroup), vk::divUp(res, kLanes), shadowLayers);
        });
    graph.pass("shadow.blur")
        .pipeline(columns_.pipeline)
        .storageImage(MOMENT_COLUMNS_ROWS, rows, Use::StorageRead)
        .storageImage(MOMENT_COLUMNS_OUT, out)
        .storageBuffer(MOMENT_COLUMNS_LAYERS, layerTable)
        .uniform(MOMENT_COLUMNS_PARAMS, params)
        .record([res, shadowLayers](PassContext& c) {
            vkCmdDispatch(c.cmd, vk::divUp(res, kLanes), vk::divUp(res, kGroup), shadowLayers);
        });
}

}  // namespace penumbra
