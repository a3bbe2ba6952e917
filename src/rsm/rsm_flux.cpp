#include "rsm/rsm_flux.h"

#include <algorithm>
#include <bit>

#include <glm/glm.hpp>

#include "rsm/bindings.h"

namespace penumbra {

RsmFluxSampler::RsmFluxSampler(vk::Allocator& alloc, uint32_t resolution, uint32_t seed)
    : alloc_(alloc), resolution_(resolution), curve_(std::bit_ceil(resolution)), seed_(seed) {
    vk::Context& ctx = alloc.context();
    const VkDescriptorType ssbo = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, tex = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    sums_ = vk::ComputeKernel(ctx, "rsm/flux_sums.comp", {{RSM_FLUX_VPLS, tex}, {RSM_FLUX_SUMS, ssbo}},
                              sizeof(gpu::RsmFluxPush));
    draw_ = vk::ComputeKernel(ctx, "rsm/flux_draw.comp",
                              {{RSM_FLUX_VPLS, tex}, {RSM_FLUX_SUMS, ssbo}, {RSM_FLUX_DRAWS, ssbo}},
                              sizeof(gpu::RsmFluxPush));
    point_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});
}

void RsmFluxSampler::addTo(FrameGraph& graph, uint32_t layers) {
    layers = std::max(layers, 1u);
    if (layers != layers_) {
        layers_ = layers;
        cdf_ = vk::Buffer(alloc_, cdfBytes(resolution_, layers), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false, "rsm-flux-cdf");
        draws_ = vk::Buffer(alloc_, 16 * layers * VkDeviceSize(RSM_FLUX_BLOCK),
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, false, "rsm-flux-draws");
    }
    const BufferHandle cdf = graph.import(cdf_), draws = graph.import(draws_);
    const ImageHandle vpls = graph.image("rsm.vpls");
    graph.publish("rsm.flux-draws", draws);
    const VkSampler point = point_.handle();
    for (uint32_t step : {0u, 1u}) {
        const gpu::RsmFluxPush pc{resolution_, layers, curve_, step, seed_};
        graph.pass(step == 0 ? "rsm.flux-runs" : "rsm.flux-cdf")
            .pipeline(sums_.pipeline)
            .sampled(RSM_FLUX_VPLS, vpls, point)
            .storageBuffer(RSM_FLUX_SUMS, cdf, Use::StorageWrite)
            .record([this, pc](PassContext& c) {
                sums_.pipeline.push(c.cmd, pc);
                if (pc.step == 0) vkCmdDispatch(c.cmd, pc.curve, pc.layerCount, 1);
                else vkCmdDispatch(c.cmd, pc.layerCount, 1, 1);
            });
    }
    const gpu::RsmFluxPush pc{resolution_, layers, curve_, 0, seed_};
    graph.pass("rsm.flux-draw")
        .pipeline(draw_.pipeline)
        .sampled(RSM_FLUX_VPLS, vpls, point)
        .storageBuffer(RSM_FLUX_SUMS, cdf, Use::StorageRead)
        .storageBuffer(RSM_FLUX_DRAWS, draws, Use::StorageWrite)
        .record([this, pc](PassContext& c) {
            draw_.pipeline.push(c.cmd, pc);
            vkCmdDispatch(c.cmd, vk::divUp(RSM_FLUX_ENTRIES, 256), pc.layerCount, 1);
        });
}

}  // namespace penumbra
