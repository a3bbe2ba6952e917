// Reflective shadow maps: the light's view of the scene stored as virtual point lights (depth ->
// position, octahedral normal, reflected flux), one array layer per shadow layer of a light.
// Not rasterized: resolved in compute (rsm.resolve) from the visibility IDs that the shadow pass
// writes for these layers ("shadow.ids"), at the RSM resolution: texel (i, j) takes the ID texel
// nearest its centre and the attributes of that triangle at its centre (depth unbiased).
#pragma once
#include <vector>

#include "core/frame_graph.h"
#include "core/scene_gpu.h"
#include "rsm/rsm_settings.h"
#include "core/light_space.h"

namespace penumbra {

// One RSM layer: which light, its light-space projection, and the row of the views buffer that
// holds that projection.
struct RsmLayerSource {
    uint32_t light;
    uint32_t viewIndex;
    LightProjection projection;  // texelSize as for the shadow map's resolution
    uint32_t shadowResolution;
    // Cascades of one directional light see the same surfaces: the gather uses one per receiver.
    uint32_t cascade = 0;       // cascade index + 1, 0 = not a cascade
    bool lastCascade = false;
    float radiusScale = 1.0f;   // keeps r_max's world size equal to the first cascade's
};

class RsmPass {
public:
    static constexpr VkFormat kDepthFormat = VK_FORMAT_R32_SFLOAT, kNormalFormat = VK_FORMAT_R16G16_SNORM,
                              kFluxFormat = VK_FORMAT_R16G16B16A16_SFLOAT, kVplFormat = VK_FORMAT_R32G32B32A32_UINT;
    // What one texel of one layer holds across the four images (the device budget's figure).
    static uint64_t texelBytes();
    // `idResolution`: the shadow map's, which the ID layers have.
    RsmPass(vk::Allocator& alloc, SceneGpu& scene, const RsmSettings& settings, uint32_t idResolution);

    // The layers of this frame (writes frame slot `slot`'s layer table; a new count re-sizes the images).
    void setLayers(const std::vector<RsmLayerSource>& layers, uint32_t slot);
    // The shadow layers the RSM layers are resolved from (ShadowMapPass::requestIds), in layer order.
    std::vector<uint32_t> shadowLayers() const;
    // rsm.resolve: reads "shadow.ids", "lights"; publishes "rsm.depth" (R32_SFLOAT: z/w of the layer's
    // projection), "rsm.normal" (RG16_SNORM octahedral), "rsm.flux" (RGBA16F), "rsm.layers".
    void addTo(FrameGraph& graph);

    uint32_t layerCount() const { return uint32_t(sources_.size()); }
    const RsmSettings& settings() const { return settings_; }
    vk::Image& depth() { return depth_; }
    vk::Image& normal() { return normal_; }
    vk::Image& flux() { return flux_; }
    const vk::Buffer& layerTable() const { return layerTable_.current(); }

private:
    vk::Allocator& alloc_;
    SceneGpu& scene_;
    RsmSettings settings_;
    uint32_t idResolution_;
    vk::DescriptorLayout layout_;
    vk::Pipeline pipeline_;
    vk::Sampler nearest_;
    std::vector<RsmLayerSource> sources_;
    vk::Image depth_, normal_, flux_;
    vk::Image vpls_;  // the three packed in one texel for the gather (rsm/resolve.comp)
    vk::BufferRing layerTable_;
};

}  // namespace penumbra
