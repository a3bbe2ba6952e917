// The edge-aware a-trous filter of the accumulated indirect irradiance (temporal_gi/filter.comp):
// iterations of a 3x3 kernel with taps 1, 2, 4, ... pixels apart, alternating between two images,
// guided by the history's geometry of this frame.
#pragma once
#include "core/frame_graph.h"
#include "temporal_gi/gi_history.h"
#include "vk/pipeline.h"

namespace penumbra {

class GiFilter {
public:
    GiFilter(vk::Allocator& alloc, uint32_t width, uint32_t height);
    static uint64_t bytes(uint64_t width, uint64_t height);
    // The filtered irradiance after `iterations` (at least 1) iterations over `history`.
    ImageHandle addTo(FrameGraph& graph, const GiHistoryImages& history, uint32_t iterations, float luminanceSigma);
    // Frees the images (a frame without GI); the next addTo makes them anew.
    void release() { images_[0] = {}, images_[1] = {}; }

private:
    vk::Allocator& alloc_;
    uint32_t width_, height_;
    vk::ComputeKernel kernel_;
    vk::Sampler nearest_;
    vk::Image images_[2];  // made by the first addTo
};

}  // namespace penumbra
