// Deferred direct lighting in compute (render/lighting.comp): every light, shadow-map visibility,
// writes the HDR image or the selected AOV.
#pragma once
#include "dsm/deep_shadow_maps.h"
#include "render/frame_graph.h"
#include "render/gbuffer_pass.h"

namespace penumbra {

class LightingPass {
public:
    LightingPass(vk::Allocator& alloc, uint32_t width, uint32_t height);
    // `shadowMask`: filtered visibility per shadowed light (ShadowMapPass::mask, written by shadow.filter).
    // `indirect`: indirect irradiance per pixel (GI on) or a 1x1 placeholder (FrameUniforms.options.x = 0).
    // `dsm`: deep shadow maps (transmittance of translucent casters, bindings 8-11).
    void addTo(FrameGraph& graph, const vk::Buffer& frame, const vk::Buffer& lights, GBufferPass& gbuffer,
               vk::Image& shadowMask, vk::Image& indirect, const DeepShadowMaps& dsm);

    vk::Image hdr;  // RGBA32F radiance (or AOV values)

private:
    vk::Allocator& alloc_;
    vk::DescriptorLayout layout_;
    vk::Pipeline pipeline_;
    vk::Sampler pointSampler_;
};

class TonemapPass {
public:
    TonemapPass(vk::Allocator& alloc, uint32_t width, uint32_t height);
    void addTo(FrameGraph& graph, vk::Image& hdr, const gpu::TonemapPush& params);

    vk::Image ldr;  // RGBA8, sRGB-encoded values in a UNORM image (storage images cannot be sRGB)

private:
    vk::Allocator& alloc_;
    vk::DescriptorLayout layout_;
    vk::Pipeline pipeline_;
};

}  // namespace penumbra
