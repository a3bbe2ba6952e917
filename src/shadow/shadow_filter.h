// shadow.filter: per pixel and shadowed light, the visibility with that light's filter (hard, PCF,
// PCSS, VSM, EVSM, MSM) into the shadow mask (RG16F array, one layer per shadowed light: r =
// visibility, g = layer code for the `cascade` AOV). The lighting pass only reads the mask, so the
// filter's cost is this pass's GPU time.
#pragma once
#include "core/frame_graph.h"
#include "vk/pipeline.h"

namespace penumbra {

class ShadowFilterPass {
public:
    explicit ShadowFilterPass(vk::Allocator& alloc);
    // Reads "frame", "lights", the G-buffer's depth and normal, "shadow.map", "shadow.moments",
    // "shadow.layers", "shadow.lights", "shadow.params"; publishes "shadow.mask".
    void addTo(FrameGraph& graph, uint32_t shadowedLights);
    vk::Image& mask() { return mask_; }

private:
    void ensureMask(uint32_t width, uint32_t height, uint32_t layers);
    vk::Allocator& alloc_;
    vk::ComputeKernel kernel_;
    vk::Sampler point_, depth_, moments_;
    vk::Image mask_;
};

}  // namespace penumbra
