#include "dsm/deep_shadow_resolve.h"

#include "dsm/bindings.h"

namespace penumbra {

DeepShadowResolvePass::DeepShadowResolvePass(vk::Allocator& alloc, DsmResources& res, bool links)
    : alloc_(alloc), res_(res), links_(links) {
    const VkDescriptorType ssbo = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    resolve_ = vk::ComputeKernel(alloc.context(), "dsm/resolve.comp",
                                 std::vector<vk::Binding>{{DSM_RESOLVE_HEADS, ssbo},
                                                          {DSM_RESOLVE_NODES, ssbo},
                                                          {DSM_RESOLVE_SIDE, ssbo},
                                                          {DSM_RESOLVE_WORK, ssbo},
                                                          {DSM_RESOLVE_RUNS, ssbo},
                                                          {DSM_RESOLVE_BUCKETS, ssbo}},
                                 sizeof(gpu::DsmPush));
    link_ = vk::ComputeKernel(alloc.context(), "dsm/link.comp",
                              std::vector<vk::Binding>{{DSM_LINK_HEADS, ssbo}, {DSM_LINK_NODES, ssbo}, {DSM_LINK_UP_LINKS, ssbo}},
                              sizeof(gpu::DsmPush));
}

// One thread per texel of every layer (8x8 tiles), or (`grid`) a fixed grid of workgroups striding
// over the listed texels, however many the frame made.
void DeepShadowResolvePass::addDispatch(PassBuilder& pass, const vk::ComputeKernel& k, bool grid) const {
    const gpu::DsmPush push = res_.push();
    pass.pipeline(k.pipeline).record([this, &k, push, grid](PassContext& c) {
        k.pipeline.push(c.cmd, push);
        if (grid)
            vkCmdDispatch(c.cmd, kGridGroups, 1, 1);
        else
            vkCmdDispatch(c.cmd, vk::divUp(res_.resolution, 8), vk::divUp(res_.resolution, 8), res_.layerCount());
    });
}

void DeepShadowResolvePass::addTo(FrameGraph& graph) {
    const BufferHandle heads = graph.import(res_.heads), nodes = graph.import(res_.nodes),
                       side = graph.import(res_.side), work = graph.import(res_.work),
                       runs = graph.import(res_.runs);
    PassBuilder resolve = graph.pass("dsm.resolve");
    resolve.storageBuffer(DSM_RESOLVE_HEADS, heads, Use::StorageWrite)  // each list's place and length
        .storageBuffer(DSM_RESOLVE_NODES, nodes, Use::StorageWrite)
        .storageBuffer(DSM_RESOLVE_SIDE, side, Use::StorageWrite)  // search keys
        .storageBuffer(DSM_RESOLVE_WORK, work, Use::StorageRead)
        .storageBuffer(DSM_RESOLVE_RUNS, runs, Use::StorageRead)
        .storageBuffer(DSM_RESOLVE_BUCKETS, graph.import(res_.buckets), Use::StorageWrite);  // zeroed for the next frame
    addDispatch(resolve, resolve_, true);
    if (!links_) return;
    PassBuilder link = graph.pass("dsm.link");
    link.storageBuffer(DSM_LINK_HEADS, heads, Use::StorageRead)
        .storageBuffer(DSM_LINK_NODES, nodes, Use::StorageWrite)
        .storageBuffer(DSM_LINK_UP_LINKS, side, Use::StorageWrite);
    addDispatch(link, link_);
}

}  // namespace penumbra
