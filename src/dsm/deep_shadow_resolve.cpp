#include "dsm/deep_shadow_resolve.h"

namespace penumbra {

DeepShadowResolvePass::DeepShadowResolvePass(vk::Allocator& alloc, DsmResources& res, bool links)
    : alloc_(alloc), res_(res), links_(links) {
    const VkDescriptorType ssbo = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    resolve_ = vk::ComputeKernel(alloc.context(), "dsm/resolve.comp", {ssbo, ssbo, ssbo, ssbo}, sizeof(gpu::DsmPush));
    link_ = vk::ComputeKernel(alloc.context(), "dsm/link.comp", {ssbo, ssbo, ssbo}, sizeof(gpu::DsmPush));
}

// One thread per texel of every layer. Both passes rewrite the nodes (binding 1) and the side buffer:
// the resolve its search keys (3), the link pass its upper links (2).
void DeepShadowResolvePass::addDispatch(PassBuilder& pass, const vk::ComputeKernel& k) const {
    const gpu::DsmPush push{{res_.resolution, res_.layerCount(), uint32_t(res_.capacity), res_.maxList}};
    pass.pipeline(k.pipeline).record([this, &k, push](PassContext& c) {
        k.pipeline.push(c.cmd, push);
        vkCmdDispatch(c.cmd, vk::divUp(res_.resolution, 8), vk::divUp(res_.resolution, 8), res_.layerCount());
    });
}

void DeepShadowResolvePass::addTo(FrameGraph& graph) {
    const BufferHandle heads = graph.import(res_.heads), nodes = graph.import(res_.nodes),
                       side = graph.import(res_.side);
    PassBuilder resolve = graph.pass("dsm.resolve");
    resolve.storageBuffer(0, heads, Use::StorageWrite)  // each list's packed place and length
        .storageBuffer(1, nodes, Use::StorageWrite)
        .storageBuffer(2, graph.import(res_.stats), Use::StorageWrite)
        .storageBuffer(3, side, Use::StorageWrite);
    addDispatch(resolve, resolve_);
    if (!links_) return;
    PassBuilder link = graph.pass("dsm.link");
    link.storageBuffer(0, heads, Use::StorageRead)
        .storageBuffer(1, nodes, Use::StorageWrite)
        .storageBuffer(2, side, Use::StorageWrite);
    addDispatch(link, link_);
}

}  // namespace penumbra
