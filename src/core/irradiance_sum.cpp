#include "core/irradiance_sum.h"

#include <string>

#include "core/irradiance_sum_bindings.h"  // shaders/core
#include "core/names.h"

namespace penumbra {

IrradianceSum::IrradianceSum(vk::Allocator& alloc, uint32_t width, uint32_t height)
    : alloc_(alloc), width_(width), height_(height) {
    constexpr VkDescriptorType kTex = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    kernel_ = vk::ComputeKernel(alloc.context(), "core/irradiance_sum.comp",
                                std::vector<vk::Binding>{{IRRADIANCE_SUM_FIRST, kTex},
                                                         {IRRADIANCE_SUM_SECOND, kTex},
                                                         {IRRADIANCE_SUM_OUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}},
                                0);
    linear_ = vk::Sampler(alloc.context(), {VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});
}

ImageHandle IrradianceSum::addTo(FrameGraph& graph) {
    const std::vector<ImageHandle> parts = graph.contributions(names::kIrradianceContribution);
    if (parts.empty()) return {};
    ImageHandle sum = parts.front();
    for (size_t k = 1; k < parts.size(); ++k) {
        if (sums_.size() < k)
            sums_.push_back(std::make_unique<vk::Image>(
                alloc_, vk::ImageDesc{VK_FORMAT_R32G32B32A32_SFLOAT, width_, height_, 1,
                                      VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, "gi-sum"}));
        const ImageHandle out = graph.import(*sums_[k - 1]);
        graph.pass("gi.sum." + std::to_string(k))
            .pipeline(kernel_.pipeline)
            .sampled(IRRADIANCE_SUM_FIRST, sum, linear_.handle())
            .sampled(IRRADIANCE_SUM_SECOND, parts[k], linear_.handle())
            .storageImage(IRRADIANCE_SUM_OUT, out)
            .record([this](PassContext& c) {
                vkCmdDispatch(c.cmd, vk::divUp(width_, 8), vk::divUp(height_, 8), 1);
            });
        sum = out;
    }
    graph.setContributions(names::kIrradianceContribution, {sum});
    return sum;
}

}  // namespace penumbra
