#include "dsm/deep_shadow_resolve.h"

namespace penumbra {

DeepShadowResolvePass::DeepShadowResolvePass(vk::Allocator& alloc, DsmResources& res, bool links)
    : alloc_(alloc), res_(res), links_(links) {
    const std::vector<VkDescriptorType> three(3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    resolve_ = vk::ComputeKernel(alloc.context(), "dsm/resolve.comp", three, sizeof(gpu::DsmPush));
    link_ = vk::ComputeKernel(alloc.context(), "dsm/link.comp", three, sizeof(gpu::DsmPush));
}

// Both kernels read the heads (binding 0) and rewrite the nodes (1); the third binding is the
// resolve's counters or the link pass's upper links. One thread per texel of every layer.
void DeepShadowResolvePass::addDispatch(FrameGraph& graph, const char* name, const vk::ComputeKernel& k,
                                        const vk::Buffer& third) const {
    const gpu::DsmPush push{{res_.resolution, res_.layerCount(), uint32_t(res_.capacity), res_.maxList}};
    graph.pass(name)
        .pipeline(k.pipeline)
        .storageBuffer(0, graph.import(res_.heads), Use::StorageRead)
        .storageBuffer(1, graph.import(res_.nodes), Use::StorageWrite)
        .storageBuffer(2, graph.import(third), Use::StorageWrite)
        .record([this, &k, push](PassContext& c) {
            k.pipeline.push(c.cmd, push);
            vkCmdDispatch(c.cmd, vk::divUp(res_.resolution, 8), vk::divUp(res_.resolution, 8), res_.layerCount());
        });
}

void DeepShadowResolvePass::addTo(FrameGraph& graph) {
    addDispatch(graph, "dsm.resolve", resolve_, res_.stats);
    if (links_) addDispatch(graph, "dsm.link", link_, res_.upLinks);
}

}  // namespace penumbra
