// Temporal accumulation of the indirect irradiance (--gi-temporal, off by default; README "Temporal
// stability"): each frame blends its "gi.irradiance" into the previous frames' accumulation, reprojected
// to where each pixel's surface point was (render/gi_history.comp), and publishes the result as
// "gi.irradiance". Two history images alternate: one is read while the other is written.
#pragma once
#include "core/frame_graph.h"
#include "core/previous_frame.h"
#include "vk/pipeline.h"

namespace penumbra {

class GiHistory {
public:
    GiHistory(vk::Allocator& alloc, uint32_t width, uint32_t height);
    // Reads "frame", "gi.irradiance", "gbuffer.depth", "gbuffer.ids", "drawn-triangles", "instances";
    // republishes "gi.irradiance". `alpha`: the new frame's weight.
    void addTo(FrameGraph& graph, float alpha);
    // The next frame starts a new accumulation (the GI that fills it changed).
    void reset() { valid_ = false; }

private:
    vk::ComputeKernel kernel_;
    vk::Sampler nearest_;
    vk::Image irradiance_[2], depth_[2];
    uint32_t next_ = 0;   // the image this frame writes
    bool valid_ = false;  // the other holds the previous frame
};

}  // namespace penumbra
