// --rsm-far flux: RSM texels drawn by their flux, for the far half of the gather's samples
// (rsm/gather.glsl). Three small passes per frame after rsm.resolve: rsm.flux-runs (running sums of
// the flux luminance along runs of a Hilbert curve over the map), rsm.flux-cdf (the runs' totals
// summed) and rsm.flux-draw (RSM_FLUX_ENTRIES stratified draws per layer), published as
// "rsm.flux-draws" (layout in shared/types.h).
#pragma once
#include <algorithm>
#include <bit>

#include "core/frame_graph.h"
#include "shared/types.h"

namespace penumbra {

class RsmFluxSampler {
public:
    // The flux CDF (one buffer, bound whole): per layer, a float per texel of the map rounded up to a
    // power of two and one per row. Shared with the device budget.
    static uint64_t cdfBytes(uint32_t resolution, uint32_t layers) {
        const uint64_t n = std::bit_ceil(resolution);
        return sizeof(float) * std::max(layers, 1u) * (n * n + n);
    }

    RsmFluxSampler(vk::Allocator& alloc, uint32_t resolution, uint32_t seed);
    // Reads "rsm.vpls"; publishes "rsm.flux-draws". A new layer count re-sizes the buffers.
    void addTo(FrameGraph& graph, uint32_t layers);
    void setSeed(uint32_t seed) { seed_ = seed; }
    const vk::Buffer& draws() const { return draws_; }

private:
    vk::Allocator& alloc_;
    uint32_t resolution_, curve_, seed_, layers_ = 0;  // curve_: the Hilbert curve's side, a power of two
    vk::ComputeKernel sums_, draw_;
    vk::Sampler point_;
    vk::Buffer cdf_, draws_;
};

}  // namespace penumbra
