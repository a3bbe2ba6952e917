#include "lighting/auto_exposure.h"

#include <cmath>

#include "lighting/lighting_bindings.h"

namespace penumbra {

AutoExposure::AutoExposure(vk::Allocator& alloc, uint32_t width, uint32_t height)
    : reduce_(alloc.context(), "lighting/exposure_reduce.comp",
              {{EXPOSURE_HDR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, {EXPOSURE_HISTOGRAM, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}},
              0),
      resolve_(alloc.context(), "lighting/exposure_resolve.comp",
               {{EXPOSURE_HISTOGRAM, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, {EXPOSURE_STATE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}},
               sizeof(gpu::AutoExposurePush)),
      groupsX_(vk::divUp(width, uint32_t(EXPOSURE_TILE))), groupsY_(vk::divUp(height, uint32_t(EXPOSURE_TILE))) {
    const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                     VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    // Per bin a uvec4 (exposure_reduce.comp): count, and the in-bin positions' sum in two words.
    histogram_ = vk::Buffer(alloc, VkDeviceSize(EXPOSURE_BINS) * 16, usage, false, "exposure.histogram");
    state_ = vk::Buffer(alloc, sizeof(gpu::AutoExposureState), usage, false, "exposure.state");
}

BufferHandle AutoExposure::addTo(FrameGraph& graph, bool run, float lowPercentile, float highPercentile) {
    const BufferHandle state = graph.import(state_);
    const BufferHandle histogram = graph.import(histogram_);
    if (!cleared_) {
        // Afterwards each resolve leaves the histogram zeroed for the next reduce.
        cleared_ = true;
        graph.pass("exposure.clear", PassKind::Transfer)
            .use(state, Use::TransferDst)
            .use(histogram, Use::TransferDst)
            .record([state, histogram](PassContext& c) {
                vkCmdFillBuffer(c.cmd, c.buffer(state).handle(), 0, VK_WHOLE_SIZE, 0);
                vkCmdFillBuffer(c.cmd, c.buffer(histogram).handle(), 0, VK_WHOLE_SIZE, 0);
            });
    }
    if (!run) return state;
    const uint32_t gx = groupsX_, gy = groupsY_;
    graph.pass("exposure.reduce")
        .pipeline(reduce_.pipeline)
        .storageImage(EXPOSURE_HDR, graph.image("hdr"), Use::StorageRead)
        .storageBuffer(EXPOSURE_HISTOGRAM, histogram, Use::StorageWrite)
        .record([gx, gy](PassContext& c) { vkCmdDispatch(c.cmd, gx, gy, 1); });
    const float rate = restart_ ? 1.0f : 1.0f - std::exp(-kFrameSeconds / kTauSeconds);
    restart_ = false;
    const gpu::AutoExposurePush push{rate, lowPercentile / 100.0f, highPercentile / 100.0f, 0};
    graph.pass("exposure.resolve")
        .pipeline(resolve_.pipeline)
        .storageBuffer(EXPOSURE_HISTOGRAM, histogram, Use::StorageWrite)
        .storageBuffer(EXPOSURE_STATE, state, Use::StorageWrite)
        .record([this, push](PassContext& c) {
            resolve_.pipeline.push(c.cmd, push);
            vkCmdDispatch(c.cmd, 1, 1, 1);
        });
    return state;
}

}  // namespace penumbra
