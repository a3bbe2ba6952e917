// Deferred direct lighting in compute (lighting/lighting.comp): every light, shadow-map visibility,
// writes the HDR image or the selected AOV.
#pragma once
#include "core/frame_graph.h"
#include "core/core_settings.h"
#include "shared/types.h"
#include "vk/pipeline.h"

namespace penumbra {

class LightingPass {
public:
    static constexpr VkFormat kHdrFormat = VK_FORMAT_R32G32B32A32_SFLOAT;  // linear radiance: the EXR output
    LightingPass(vk::Allocator& alloc, uint32_t width, uint32_t height);
    // Reads by name: "frame", "lights", the G-buffer, "shadow.mask" (filtered visibility per shadowed
    // light), "gi.irradiance" (indirect irradiance per pixel, or a 1x1 placeholder when
    // FrameUniforms.giValid = 0), and the deep shadow maps' lookup buffers "dsm.lights",
    // "dsm.heads", "dsm.nodes", "dsm.side" (bindings 8-11), and for the velocity AOV "gbuffer.ids"
    // (a 1x1 placeholder on the classic path, FrameUniforms.visibilityIds = 0), "drawn-triangles" and
    // "instances", and "sky.irradiance" (the visible sky's, added to the direct light; a 1x1 black
    // image without a sky); writes "probe" (the pixel probe, FrameUniforms.probeX, probeY). `sky` is the
    // background's radiance (lighting/gpu_sky.h). Publishes "hdr".
    void addTo(FrameGraph& graph, ImageHandle sky);

    vk::Image hdr;  // RGBA32F radiance (or AOV values)

private:
    vk::DescriptorLayout layout_;
    vk::Pipeline pipeline_;
    vk::Sampler pointSampler_;
};

// Debug views of light-space images (AOVs rsm-depth, rsm-normal, rsm-flux, shadow-map): overwrites
// "hdr" with one layer of the published source image, letterboxed.
class DebugViewPass {
public:
    explicit DebugViewPass(vk::Context& ctx);
    // Adds the pass when `aov` is one of these views and its source is published this frame.
    void addTo(FrameGraph& graph, Aov aov, uint32_t layer);

private:
    vk::ComputeKernel kernel_;
    vk::Sampler nearest_;
};

class TonemapPass {
public:
    TonemapPass(vk::Allocator& alloc, uint32_t width, uint32_t height);
    // Reads "hdr" and, when params.autoExposure, the auto exposure's state (lighting/auto_exposure.h);
    // publishes "ldr".
    void addTo(FrameGraph& graph, const gpu::TonemapPush& params, BufferHandle exposure);

    vk::Image ldr;  // RGBA8, sRGB-encoded values in a UNORM image (storage images cannot be sRGB)

private:
    vk::DescriptorLayout layout_;
    vk::Pipeline pipeline_;
};

}  // namespace penumbra
