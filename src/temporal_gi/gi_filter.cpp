#include "temporal_gi/gi_filter.h"

#include <string>

#include "core/names.h"
#include "shared/types.h"
#include "temporal_gi/bindings.h"
#include "vk/format_bytes.h"

namespace penumbra {
namespace {

constexpr VkFormat kFilteredFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

}  // namespace

GiFilter::GiFilter(vk::Allocator& alloc, uint32_t width, uint32_t height)
    : alloc_(alloc), width_(width), height_(height) {
    vk::Context& ctx = alloc.context();
    constexpr VkDescriptorType kTex = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    kernel_ = vk::ComputeKernel(ctx, "temporal_gi/filter.comp",
                                {{GI_FILTER_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                 {GI_FILTER_GUIDE, kTex},
                                 {GI_FILTER_INPUT, kTex},
                                 {GI_FILTER_MOMENTS, kTex},
                                 {GI_FILTER_OUTPUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}},
                                sizeof(gpu::GiFilterPush));
    nearest_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});
}

uint64_t GiFilter::bytes(uint64_t width, uint64_t height) {
    return 2 * width * height * vk::texelBytes(kFilteredFormat);
}

ImageHandle GiFilter::addTo(FrameGraph& graph, const GiHistoryImages& history, uint32_t iterations,
                            float luminanceSigma) {
    if (!images_[0].handle()) {
        const VkImageUsageFlags usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
        for (vk::Image& image : images_)
            image = vk::Image(alloc_, {kFilteredFormat, width_, height_, 1, usage, "gi-filtered"});
    }
    const VkSampler nearest = nearest_.handle();
    ImageHandle input = history.color;
    for (uint32_t k = 0; k < iterations; ++k) {
        const ImageHandle out = graph.import(images_[k % 2]);
        const gpu::GiFilterPush push{1u << k, k == 0 ? 1u : 0u, luminanceSigma, 0};
        graph.pass("gi.filter-" + std::to_string(k))
            .pipeline(kernel_.pipeline)
            .uniform(GI_FILTER_FRAME, graph.buffer(names::kFrame))
            .sampled(GI_FILTER_GUIDE, history.geometry, nearest)
            .sampled(GI_FILTER_INPUT, input, nearest)
            .sampled(GI_FILTER_MOMENTS, history.moments, nearest)
            .storageImage(GI_FILTER_OUTPUT, out)
            .record([this, out, push](PassContext& c) {
                kernel_.pipeline.push(c.cmd, push);
                const vk::Image& image = c.image(out);
                vkCmdDispatch(c.cmd, vk::divUp(image.width(), 8), vk::divUp(image.height(), 8), 1);
            });
        input = out;
    }
    return input;
}

}  // namespace penumbra
