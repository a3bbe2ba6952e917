// Exposure like a camera's (`--exposure auto`): the log-average luminance of the geometry pixels of
// "hdr" (the sky, alpha 0, left out) maps to middle grey 0.18, as `eval` exposes its figures. Two
// compute passes ("exposure.reduce" over 16x16 tiles, "exposure.resolve" in one workgroup) write
// gpu::AutoExposureState, which the tone mapper reads; from frame to frame the exposure approaches
// its target exponentially in log space (Filament's adaptation), the first frame taking it at once.
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
    // The state buffer, cleared on the first frame; with `run`, this frame's passes over "hdr".
    BufferHandle addTo(FrameGraph& graph, bool run);
    // The next run takes its target at once (a new scene, a cut, exposure switched back to auto).
    void restart() { restart_ = true; }
    const vk::Buffer& state() const { return state_; }

private:
    vk::ComputeKernel reduce_, resolve_;
    vk::Buffer partials_, state_;
    uint32_t groupsX_, groupsY_;
    bool cleared_ = false, restart_ = true;
};

}  // namespace penumbra
