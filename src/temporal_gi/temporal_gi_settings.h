// Settings of the temporal-GI module (src/temporal_gi): how the indirect irradiance is accumulated
// over frames and filtered.
#pragma once
#include <cstdint>

namespace penumbra {

struct TemporalGiSettings {
    // The least weight of a new frame: a still history averages up to 1 / minWeight frames. 0.05: the
    // noise of a still view falls to a sixth of one frame's; a lower floor converges further but
    // carries a change that no detector sees (a moving object's bounce) longer.
    float minWeight = 0.05f;
    // A light that turns by this many degrees in a frame (or a spot or point light that moves by this
    // share of the scene's size, in the same measure) restarts the history; a smaller change raises
    // the new frame's weight to (change / resetAngle)^2, so a slow sun keeps most of its history.
    float resetAngle = 10.0f;
    // Iterations of the edge-aware a-trous filter (3x3 taps 1, 2, 4, 8 ... pixels apart: four reach 15
    // pixels); 0: none.
    uint32_t filterIterations = 4;
    // Its luminance edge stop, in standard deviations of a pixel's accumulated estimate.
    float luminanceSigma = 4.0f;
};

}  // namespace penumbra
