// Standard shadow maps (seed 004): depth rendered from each shadowed directional or spot light into
// one layer of a D32 array image; constant + slope-scaled rasterizer bias at render time, normal
// offset at lookup time (render/lighting.comp).
#pragma once
#include <vector>

#include "render/frame_graph.h"
#include "render/scene_gpu.h"
#include "shadow/light_space.h"

namespace penumbra {

struct ShadowSettings {
    uint32_t resolution = 2048;
    // Rasterizer depth bias. D32_SFLOAT's constant unit is 2^(e-23) of the primitive's largest depth
    // exponent, so the constant term is small; the slope term does the work on slanted receivers.
    float depthBiasConstant = 4.0f;
    float depthBiasSlope = 1.5f;
    // Receiver offset along its normal, in shadow texels (texel world size at the receiver).
    float normalOffset = 1.0f;
};

class ShadowMapPass {
public:
    ShadowMapPass(vk::Allocator& alloc, SceneGpu& scene, const ShadowSettings& settings,
                  VkDescriptorSetLayout drawLayout);

    // Gives each shadowed light a layer and a light-space projection. Lights of types without a
    // shadow technique yet (point) stay unshadowed: listed in `unsupported`.
    void assign(const std::vector<Light>& lights, std::vector<int>& layerOfLight,
                std::vector<LightProjection>& projections, std::vector<std::string>& unsupported);

    // Records one layer per projection; view k of `views` is layer k's matrix (firstView + k).
    void addTo(FrameGraph& graph, const vk::Buffer& views, uint32_t firstView, uint32_t layerCount);

    vk::Image& shadowMap() { return map_; }
    const ShadowSettings& settings() const { return settings_; }

private:
    void ensureLayers(uint32_t layers);
    vk::Allocator& alloc_;
    SceneGpu& scene_;
    ShadowSettings settings_;
    VkDescriptorSetLayout drawLayout_;
    vk::Pipeline opaque_, masked_;
    vk::Image map_;
};

}  // namespace penumbra
