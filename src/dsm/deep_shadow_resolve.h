// DSM resolve (compute), after the build counted each texel's nodes: dsm.offsets gives each texel a
// run in the side buffer (dsm/offsets.comp), dsm.scatter writes every node's index into its texel's
// run (dsm/scatter.comp), dsm.resolve sorts each texel's nodes and keeps its nearest `maxList` with
// their cumulative transmittance (dsm/resolve.comp); then, with `--dsm-lookup links`, dsm.link links
// every node to its right and upper neighbour texels' lists (dsm/link.comp) for the lookup's filter
// (the default binary search needs no links). Separate dispatches: each needs all of the previous.
#pragma once
#include "dsm/dsm_resources.h"
#include "render/frame_graph.h"

namespace penumbra {

class DeepShadowResolvePass {
public:
    DeepShadowResolvePass(vk::Allocator& alloc, DsmResources& res, bool links);
    void addTo(FrameGraph& graph);

private:
    void addDispatch(PassBuilder& pass, const vk::ComputeKernel& k, bool grid = false) const;
    static constexpr uint32_t kGridGroups = 4096;
    vk::Allocator& alloc_;
    DsmResources& res_;
    vk::ComputeKernel offsets_, scatter_, resolve_, link_;
    bool links_;
};

}  // namespace penumbra
