// Exposure like a camera's (`--exposure auto`): the mean log luminance of the geometry pixels of "hdr"
// (the sky, alpha 0, left out) ranked between two percentiles (`--exposure-percentiles`) maps to
// middle grey 0.18, as `eval` exposes its figures over all of them. Two compute passes write
// gpu::AutoExposureState, which the tone mapper reads: "exposure.reduce" builds a luminance histogram
// in log2 space (lighting_bindings.h gives its bins and range) with shared-memory atomics over 32x32
// tiles, "exposure.resolve" (one workgroup) averages the bins inside the window. From frame to frame
// the exposure approaches its target exponentially in log space (Filament's adaptation), the first
// frame taking it at once.
#pragma once
#include "core/frame_graph.h"
#include "shared/types.h"
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace penumbra {

class AutoExposure {
public:
    // The adaptation's time constant and the frame interval it assumes (a frame count, not a clock:
    // sequences come out the same however fast they render).
    static constexpr float kTauSeconds = 0.5f, kFrameSeconds = 1.0f / 60.0f;

    AutoExposure(vk::Allocator& alloc, uint32_t width, uint32_t height);
    // The state and histogram buffers, cleared on the first frame; with `run`, this frame's passes over
    // "hdr", metering the pixels ranked between the percentiles `low` and `high` (0 <= low < high <= 100).
    BufferHandle addTo(FrameGraph& graph, bool run, float lowPercentile, float highPercentile);
    // The next run takes its target at once (a new scene, a cut, exposure switched back to auto).
    void restart() { restart_ = true; }
    const vk::Buffer& state() const { return state_; }

private:
    vk::ComputeKernel reduce_, resolve_;
    vk::Buffer histogram_, state_;
    uint32_t groupsX_, groupsY_;
    bool cleared_ = false, restart_ = true;
};

}  // namespace penumbra
