// DSM resolve (compute): per texel, sort the list and keep its nearest `maxList` nodes with their
// cumulative transmittance (dsm/resolve.comp), then link every node to its right and upper
// neighbour texels' lists (dsm/link.comp) for the lookup's filter (`--dsm-lookup links`; the
// default binary search needs no links). Two dispatches, because a link needs the neighbour's list
// sorted.
#pragma once
#include "dsm/dsm_resources.h"
#include "render/frame_graph.h"

namespace penumbra {

class DeepShadowResolvePass {
public:
    DeepShadowResolvePass(vk::Allocator& alloc, DsmResources& res, bool links);
    void addTo(FrameGraph& graph);

private:
    void addDispatch(PassBuilder& pass, const vk::ComputeKernel& k) const;
    vk::Allocator& alloc_;
    DsmResources& res_;
    vk::ComputeKernel resolve_, link_;
    bool links_;
};

}  // namespace penumbra
