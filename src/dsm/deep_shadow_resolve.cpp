#include "dsm/deep_shadow_resolve.h"

namespace penumbra {

DeepShadowResolvePass::DeepShadowResolvePass(vk::Allocator& alloc, DsmResources& res) : alloc_(alloc), res_(res) {
    const std::vector<VkDescriptorType> three(3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    resolve_ = vk::ComputeKernel(alloc.context(), "dsm/resolve.comp", three, sizeof(gpu::DsmPush));
    link_ = vk::ComputeKernel(alloc.context(), "dsm/link.comp", three, sizeof(gpu::DsmPush));
}

// Both kernels read the heads (binding 0) and rewrite the nodes (1); the third binding is the
// resolve's counters or the link pass's upper links. One thread per texel of every layer.
void DeepShadowResolvePass::dispatch(VkCommandBuffer cmd, const vk::ComputeKernel& k, const vk::Buffer& third) const {
    k.pipeline.bind(cmd);
    vk::DescriptorWrites().storageBuffer(0, res_.heads).storageBuffer(1, res_.nodes).storageBuffer(2, third)
        .push(alloc_.context(), cmd, k.pipeline);
    const gpu::DsmPush push{{res_.resolution, res_.layerCount(), uint32_t(res_.capacity), res_.maxList}};
    k.pipeline.push(cmd, push);
    vkCmdDispatch(cmd, vk::divUp(res_.resolution, 8), vk::divUp(res_.resolution, 8), res_.layerCount());
}

void DeepShadowResolvePass::addTo(FrameGraph& graph) {
    PassDesc resolve{"dsm.resolve", PassKind::Compute, {}, {}, {}};
    resolve.buffers = {{&res_.heads, Use::StorageRead}, {&res_.nodes, Use::StorageWrite},
                       {&res_.stats, Use::StorageWrite}};
    resolve.record = [this](VkCommandBuffer cmd) { dispatch(cmd, resolve_, res_.stats); };
    graph.add(std::move(resolve));

    PassDesc link{"dsm.link", PassKind::Compute, {}, {}, {}};
    link.buffers = {{&res_.heads, Use::StorageRead}, {&res_.nodes, Use::StorageWrite},
                    {&res_.upLinks, Use::StorageWrite}};
    link.record = [this](VkCommandBuffer cmd) { dispatch(cmd, link_, res_.upLinks); };
    graph.add(std::move(link));
}

}  // namespace penumbra
