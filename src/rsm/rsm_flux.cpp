#include "rsm/rsm_flux.h"

#include <algorithm>
#include <bit>

#include <glm/glm.hpp>

namespace penumbra {

RsmFluxSampler::RsmFluxSampler(vk::Allocator& alloc, uint32_t resolution, uint32_t seed)
    : alloc_(alloc), resolution_(resolution), curve_(std::bit_ceil(resolution)), seed_(seed) {
    vk::Context& ctx = alloc.context();
    const VkDescriptorType ssbo = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, tex = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    sums_ = vk::ComputeKernel(ctx, "rsm/flux_sums.comp", {tex, ssbo}, sizeof(glm::uvec4));
    draw_ = vk::ComputeKernel(ctx, "rsm/flux_draw.comp", {tex, ssbo, ssbo}, sizeof(glm::uvec4));
    point_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});
}

void RsmFluxSampler::addTo(FrameGraph& graph, uint32_t layers) {
    layers = std::max(layers, 1u);
    const VkDeviceSize n = curve_;
    if (layers != layers_) {
        layers_ = layers;
        cdf_ = vk::Buffer(alloc_, 4 * layers * (n * n + n), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false, "rsm-flux-cdf");
        draws_ = vk::Buffer(alloc_, 16 * layers * VkDeviceSize(RSM_FLUX_BLOCK),
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, false, "rsm-flux-draws");
    }
    const BufferHandle cdf = graph.import(cdf_), draws = graph.import(draws_);
    const ImageHandle vpls = graph.image("rsm.vpls");
    graph.publish("rsm.flux-draws", draws);
    const VkSampler point = point_.handle();
    for (uint32_t step : {0u, 1u}) {
        const glm::uvec4 pc{resolution_, layers, curve_, step};
        graph.pass(step == 0 ? "rsm.flux-runs" : "rsm.flux-cdf")
            .pipeline(sums_.pipeline)
            .sampled(0, vpls, point)
            .storageBuffer(1, cdf, Use::StorageWrite)
            .record([this, pc](PassContext& c) {
                sums_.pipeline.push(c.cmd, pc);
                if (pc.w == 0) vkCmdDispatch(c.cmd, pc.z, pc.y, 1);
                else vkCmdDispatch(c.cmd, pc.y, 1, 1);
            });
    }
    const glm::uvec4 pc{resolution_, layers, curve_, seed_};
    graph.pass("rsm.flux-draw")
        .pipeline(draw_.pipeline)
        .sampled(0, vpls, point)
        .storageBuffer(1, cdf, Use::StorageRead)
        .storageBuffer(2, draws, Use::StorageWrite)
        .record([this, pc](PassContext& c) {
            draw_.pipeline.push(c.cmd, pc);
            vkCmdDispatch(c.cmd, vk::divUp(RSM_FLUX_ENTRIES, 256), pc.y, 1);
        });
}

}  // namespace penumbra
