// Filterable shadow maps (VSM, EVSM, MSM): moments computed from the depth map in compute (the
// raster pass stays depth-only) and blurred separably: shadow.moments = depth -> moments + blur
// along x, shadow.blur = blur along y. Only layers of lights with a moment filter get a moment
// layer (GpuShadowLayer.info.y); the others are skipped by whole workgroups.
#pragma once
#include "core/frame_graph.h"
#include "vk/pipeline.h"

namespace penumbra {

class ShadowMoments {
public:
    ShadowMoments(vk::Allocator& alloc, uint32_t resolution);
    // RGBA32F arrays of `layers` moment layers (0: a 1x1 placeholder, no passes are added).
    void resize(uint32_t layers);
    // Reads "shadow.map", "shadow.layers", "shadow.params"; publishes "shadow.moments" (always).
    void addTo(FrameGraph& graph);
    vk::Image& moments() { return moments_; }

private:
    vk::Allocator& alloc_;
    uint32_t resolution_;
    uint32_t layers_ = ~0u;
    vk::ComputeKernel rows_, columns_;
    vk::Sampler nearest_;
    vk::Image rowMoments_, moments_;
};

}  // namespace penumbra
