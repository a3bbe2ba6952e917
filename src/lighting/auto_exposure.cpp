#include "lighting/auto_exposure.h"

#include <cmath>

#include "lighting/lighting_bindings.h"

namespace penumbra {

AutoExposure::AutoExposure(vk::Allocator& alloc, uint32_t width, uint32_t height)
    : reduce_(alloc.context(), "lighting/exposure_reduce.comp",
              {{EXPOSURE_HDR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, {EXPOSURE_PARTIALS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}},
              0),
      resolve_(alloc.context(), "lighting/exposure_resolve.comp",
               {{EXPOSURE_PARTIALS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, {EXPOSURE_STATE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}},
               sizeof(gpu::AutoExposurePush)),
      groupsX_(vk::divUp(width, 16u)), groupsY_(vk::divUp(height, 16u)) {
    const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                     VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    partials_ = vk::Buffer(alloc, VkDeviceSize(groupsX_) * groupsY_ * 8, usage, false, "exposure.partials");
    state_ = vk::Buffer(alloc, sizeof(gpu::AutoExposureState), usage, false, "exposure.state");
}

BufferHandle AutoExposure::addTo(FrameGraph& graph, bool run) {
    const BufferHandle state = graph.import(state_);
    if (!cleared_) {
        cleared_ = true;
        graph.pass("exposure.clear", PassKind::Transfer).use(state, Use::TransferDst).record([state](PassContext& c) {
            vkCmdFillBuffer(c.cmd, c.buffer(state).handle(), 0, VK_WHOLE_SIZE, 0);
        });
    }
    if (!run) return state;
    const BufferHandle partials = graph.import(partials_);
    const uint32_t gx = groupsX_, gy = groupsY_;
    graph.pass("exposure.reduce")
        .pipeline(reduce_.pipeline)
        .storageImage(EXPOSURE_HDR, graph.image("hdr"), Use::StorageRead)
        .storageBuffer(EXPOSURE_PARTIALS, partials, Use::StorageWrite)
        .record([gx, gy](PassContext& c) { vkCmdDispatch(c.cmd, gx, gy, 1); });
    const float rate = restart_ ? 1.0f : 1.0f - std::exp(-kFrameSeconds / kTauSeconds);
    restart_ = false;
    const gpu::AutoExposurePush push{gx * gy, rate, 0, 0};
    graph.pass("exposure.resolve")
        .pipeline(resolve_.pipeline)
        .storageBuffer(EXPOSURE_PARTIALS, partials)
        .storageBuffer(EXPOSURE_STATE, state, Use::StorageWrite)
        .record([this, push](PassContext& c) {
            resolve_.pipeline.push(c.cmd, push);
            vkCmdDispatch(c.cmd, 1, 1, 1);
        });
    return state;
}

}  // namespace penumbra
