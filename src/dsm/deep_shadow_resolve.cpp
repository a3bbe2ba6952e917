#include "dsm/deep_shadow_resolve.h"

namespace penumbra {

DeepShadowResolvePass::DeepShadowResolvePass(vk::Allocator& alloc, DsmResources& res, bool links)
    : alloc_(alloc), res_(res), links_(links) {
    const VkDescriptorType ssbo = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    resolve_ = vk::ComputeKernel(alloc.context(), "dsm/resolve.comp", {ssbo, ssbo, ssbo, ssbo}, sizeof(gpu::DsmPush));
    link_ = vk::ComputeKernel(alloc.context(), "dsm/link.comp", {ssbo, ssbo, ssbo}, sizeof(gpu::DsmPush));
}

// One thread per texel of every layer. The resolve rewrites the heads (binding 0: each list's packed
// place and length), the nodes (1), its counters (2) and the search keys (3, the side buffer); the
// link pass reads the heads and writes the nodes' right links and the side buffer's upper links.
void DeepShadowResolvePass::addDispatch(FrameGraph& graph, const char* name, const vk::ComputeKernel& k) const {
    const gpu::DsmPush push{{res_.resolution, res_.layerCount(), uint32_t(res_.capacity), res_.maxList}};
    const bool resolve = &k == &resolve_;
    PassBuilder pass = graph.pass(name);
    pass.pipeline(k.pipeline)
        .storageBuffer(0, graph.import(res_.heads), resolve ? Use::StorageWrite : Use::StorageRead)
        .storageBuffer(1, graph.import(res_.nodes), Use::StorageWrite)
        .storageBuffer(2, graph.import(resolve ? res_.stats : res_.side), Use::StorageWrite);
    if (resolve) pass.storageBuffer(3, graph.import(res_.side), Use::StorageWrite);
    pass.record([this, &k, push](PassContext& c) {
            k.pipeline.push(c.cmd, push);
            vkCmdDispatch(c.cmd, vk::divUp(res_.resolution, 8), vk::divUp(res_.resolution, 8), res_.layerCount());
        });
}

void DeepShadowResolvePass::addTo(FrameGraph& graph) {
    addDispatch(graph, "dsm.resolve", resolve_);
    if (links_) addDispatch(graph, "dsm.link", link_);
}

}  // namespace penumbra
