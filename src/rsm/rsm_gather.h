// RSM indirect light: the gather (full resolution, or low resolution + interpolation + a compacted
// full gather of the pixels interpolation cannot serve). Output: indirect irradiance per pixel.
#pragma once
#include <vector>

#include "render/frame_graph.h"
#include "render/gbuffer_pass.h"
#include "rsm/rsm_pass.h"

namespace penumbra {

// The polar sample pattern of Dachsbacher & Stamminger: xy = uv offset, z = weight (normalised so
// that the weighted sum estimates the sum over every RSM texel of the r_max disc).
std::vector<glm::vec4> rsmSamplePattern(const RsmSettings& settings);

class RsmGather {
public:
    RsmGather(vk::Allocator& alloc, vk::CommandContext& cmd, uint32_t width, uint32_t height,
              const RsmSettings& settings);
    void addTo(FrameGraph& graph, const vk::Buffer& frame, GBufferPass& gbuffer, RsmPass& rsm);

    vk::Image& irradiance() { return irradiance_; }
    // Fraction of full-resolution pixels gathered in full by the interpolated path in the last frame.
    double fallbackFraction();

private:
    gpu::RsmPush constants(uint32_t mode, uint32_t layers) const;
    PassDesc gatherPass(const char* name, uint32_t mode, vk::Image& out, const vk::Buffer& frame, GBufferPass& g,
                        RsmPass& rsm);
    vk::Allocator& alloc_;
    vk::CommandContext& cmd_;
    RsmSettings settings_;
    uint32_t width_, height_, lowWidth_, lowHeight_;
    vk::ComputeKernel gather_, interpolate_, args_;
    vk::Sampler pointSampler_;
    vk::Image irradiance_, low_;
    vk::Buffer samples_, pixelList_, dispatchArgs_;
};

}  // namespace penumbra
