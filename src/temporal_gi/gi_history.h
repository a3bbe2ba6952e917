// The GI history: this frame's indirect irradiance blended into the frames before it, reprojected to
// where each pixel's surface point was (temporal_gi/accumulate.comp). Two sets of images alternate:
// one is read while the other is written. Each holds the accumulated irradiance and the frames it
// spans, the luminance's first two moments (the spatial filter's noise estimate), and the view depth
// and normal that tell, next frame, which history pixels still show the same surface.
#pragma once
#include "core/frame_graph.h"
#include "vk/pipeline.h"

namespace penumbra {

struct GiHistoryImages {
    ImageHandle color, moments;  // this frame's accumulation
    ImageHandle geometry;        // this frame's view depth and normal (the spatial filter's guide)
};

// This frame's weights: GiAccumulatePush's minWeight and changeWeight, and the GI technique's measured
// change of its light (names::kGiChange) where one was published.
struct GiBlend {
    float minWeight = 0.05f;
    float changeWeight = 0.0f;
    ImageHandle change;       // none: nothing measured this frame
    uint32_t changePixels = 0;
    float lagTolerance = 1.0f;  // the technique's (core/names.h GiChange)
};

class GiHistory {
public:
    GiHistory(vk::Allocator& alloc, uint32_t width, uint32_t height);
    // Device bytes of the history at a width x height image.
    static uint64_t bytes(uint64_t width, uint64_t height);
    // Reads "frame", `current`, the G-buffer's depth, normal, the previous-frame inputs and the blend's
    // change image.
    GiHistoryImages addTo(FrameGraph& graph, ImageHandle current, const GiBlend& blend);
    // The next frame starts a new history.
    void reset() { valid_ = false; }
    // Frees the images (a frame without GI); the next addTo makes them anew.
    void release();

private:
    void allocate();
    vk::Allocator& alloc_;
    uint32_t width_, height_;
    ImageHandle addChangeWeight(FrameGraph& graph, const GiBlend& blend);
    vk::ComputeKernel kernel_, changeWeight_;
    vk::Sampler nearest_;
    vk::Image color_[2], moments_[2], geometry_[2];  // made by the first addTo
    vk::Image weights_;  // change_weight.comp's, sized as the last change image
    uint32_t next_ = 0;   // the set this frame writes
    bool valid_ = false;  // the other holds the previous frame
};

}  // namespace penumbra
