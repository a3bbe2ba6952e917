// DSM resolve (compute), after the build stored each texel's fragments in its run: dsm.resolve sorts
// them and keeps the nearest `maxList` with their cumulative transmittance (dsm/resolve.comp); then,
// with `--dsm-lookup links`, dsm.link links every node to its right and upper neighbour texels' lists
// (dsm/link.comp) for the lookup's filter (the default binary search needs no links). Two dispatches,
// because a link needs the neighbour's list sorted.
#pragma once
#include "dsm/dsm_resources.h"
#include "core/frame_graph.h"

namespace penumbra {

class DeepShadowResolvePass {
public:
    DeepShadowResolvePass(vk::Allocator& alloc, DsmResources& res, bool links);
    void addTo(FrameGraph& graph);

private:
    void addDispatch(PassBuilder& pass, const vk::ComputeKernel& k, bool grid = false) const;
    static constexpr uint32_t kGridGroups = 4096;  // the resolve's: enough to fill a large GPU
    vk::Allocator& alloc_;
    DsmResources& res_;
    vk::ComputeKernel resolve_, link_;
    bool links_;
};

}  // namespace penumbra
