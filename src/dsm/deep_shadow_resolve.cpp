#include "dsm/deep_shadow_resolve.h"

namespace penumbra {

DeepShadowResolvePass::DeepShadowResolvePass(vk::Allocator& alloc, DsmResources& res, bool links)
    : alloc_(alloc), res_(res), links_(links) {
    const VkDescriptorType ssbo = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    resolve_ = vk::ComputeKernel(alloc.context(), "dsm/resolve.comp", {ssbo, ssbo, ssbo, ssbo, ssbo, ssbo},
                                 sizeof(gpu::DsmPush));  // heads, nodes, side, work, runs, buckets
    link_ = vk::ComputeKernel(alloc.context(), "dsm/link.comp", {ssbo, ssbo, ssbo}, sizeof(gpu::DsmPush));
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
    resolve.storageBuffer(0, heads, Use::StorageWrite)  // each list's place and length
        .storageBuffer(1, nodes, Use::StorageWrite)
        .storageBuffer(2, side, Use::StorageWrite)  // search keys
        .storageBuffer(3, work, Use::StorageRead)
        .storageBuffer(4, runs, Use::StorageRead)
        .storageBuffer(5, graph.import(res_.buckets), Use::StorageWrite);  // zeroed for the next frame
    addDispatch(resolve, resolve_, true);
    if (!links_) return;
    PassBuilder link = graph.pass("dsm.link");
    link.storageBuffer(0, heads, Use::StorageRead)
        .storageBuffer(1, nodes, Use::StorageWrite)
        .storageBuffer(2, side, Use::StorageWrite);
    addDispatch(link, link_);
}

}  // namespace penumbra
