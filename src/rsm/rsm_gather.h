// RSM indirect light: the gather (full resolution, or low resolution + interpolation + a compacted
// full gather of the pixels interpolation cannot serve). Output: indirect irradiance per pixel.
#pragma once
#include <vector>

#include "core/frame_graph.h"
#include "core/names.h"
#include "rsm/rsm_pass.h"

namespace penumbra {

// The polar sample pattern of Dachsbacher & Stamminger: xy = uv offset, z = weight (normalised so
// that the weighted sum estimates the sum over every RSM texel of the r_max disc).
std::vector<glm::vec4> rsmSamplePattern(const RsmSettings& settings);

class RsmGather {
public:
    // The interpolated mode's list of pixels to gather exactly: a uvec4 header, then a uvec2 per pixel.
    // Shared with the device budget.
    static uint64_t pixelListBytes(uint32_t width, uint32_t height) {
        return sizeof(glm::uvec4) + sizeof(glm::uvec2) * uint64_t(width) * height;
    }
    // The temporal gradients' kept samples (two frames') and their change image.
    static uint64_t gradientBytes(uint32_t width, uint32_t height, uint32_t lowResFactor);
    RsmGather(vk::Allocator& alloc, vk::CommandContext& cmd, uint32_t width, uint32_t height,
              const RsmSettings& settings);
    // Reads "frame", the G-buffer, the RSM ("rsm.*", "rsm.flux-draws" where published); publishes
    // "gi.irradiance", and "gi.change" (names::kGiChange) in a frame that adds to a history after
    // another that did. `accumulation`: the temporal-GI module's word (null: no history).
    void addTo(FrameGraph& graph, uint32_t layerCount, uint32_t slot, const GiAccumulation* accumulation);
    // Per-frame values (samples, radius, seed, weights, thresholds); mode, resolution and the low-res
    // factor size resources and must not change.
    void setSettings(const RsmSettings& settings);

    vk::Image& irradiance() { return irradiance_; }
    // The temporal gradients of the last frame that measured them (names::kGiChange).
    vk::Image& change() { return change_; }
    GiChange& changeTexel() { return changeTexel_; }
    // Fraction of full-resolution pixels gathered in full by the interpolated path in the last frame.
    double fallbackFraction();

private:
    gpu::RsmPush constants(uint32_t mode, uint32_t layers) const;
    uint32_t visibilityMode() const;
    uint32_t sampleCount() const;
    static bool shiftedRadii(const RsmSettings& s);
    bool drawsByFlux() const;
    uint32_t lanes(uint32_t mode) const;  // invocations per receiver of a gather mode
    void addGather(FrameGraph& graph, const char* name, uint32_t mode, ImageHandle out, uint32_t layers);
    void addGradient(FrameGraph& graph, uint32_t layers);
    vk::Allocator& alloc_;
    vk::CommandContext& cmd_;
    RsmSettings settings_;
    uint32_t width_, height_, lowWidth_, lowHeight_;
    vk::ComputeKernel gather_, interpolate_, args_;
    vk::Sampler pointSampler_;
    vk::Image irradiance_, low_;
    std::vector<glm::vec4> pattern_, framePattern_;  // `samples`; `frameSamples` (while accumulating)
    bool accumulating_ = false;                       // this frame adds to a GI history
    uint32_t frameSeed_ = 0;
    vk::BufferRing samples_;  // the pattern, rewritten each frame into the frame slot's copy
    vk::Buffer pixelList_, dispatchArgs_, emptyBuffer_;
    bool fluxDraws_ = false;  // "rsm.flux-draws" is published this frame
    vk::ComputeKernel gatherFlux_;  // --rsm-far flux with shifted radii, the default (rsm/gather_flux.comp)
    // Temporal gradients (shared/types.h GpuGradientSample): the low-resolution gather of a frame that
    // adds to a history keeps one receiver of each 2x2 block of cells in gradientSamples_[keep_]; the
    // next such frame gathers them again with the kept frame's seed into change_.
    uint32_t blocksWidth_ = 0, blocksHeight_ = 0;
    vk::Buffer gradientSamples_[2];
    vk::Image change_;
    GiChange changeTexel_;
    uint32_t keep_ = 0;
    uint64_t framesKept_ = 0;  // frames whose low-resolution gather kept samples
    struct Kept {
        bool valid = false;
        uint32_t seed = 0, samples = 0;
    } kept_;  // what the samples in gradientSamples_[1 - keep_] were gathered with
};

}  // namespace penumbra
