// The shadow depth pass: every layer of every shadowed light in one layered render-pass instance.
// One instanced draw per scene draw and light renders all of the light's layers (instance = layer):
// cascades and cube faces through shadow/shadow.vert, paraboloid hemispheres through a tessellated
// pipeline (shadow/paraboloid.*) because the paraboloid mapping bends straight edges.
// Depth only: opaque casters have no fragment shader, alpha-masked ones only discard.
#pragma once
#include "render/scene_gpu.h"
#include "shadow/shadow_layout.h"

namespace penumbra {

class ShadowRaster {
public:
    ShadowRaster(vk::Context& ctx, const SceneGpu& scene, const ShadowSettings& settings,
                 VkDescriptorSetLayout drawLayout);
    // The pipeline whose set 0 (the scene's draw set) the pass declares; the others share its layout.
    const vk::Pipeline& setLayoutPipeline() const { return layered_.opaque; }
    // Clears all layers of `map` and renders those of every light (paraboloidOnly: of paraboloid point
    // lights only, the others being the compute rasterizer's); layer k uses row firstView + k of the
    // views buffer bound in the pass's draw set.
    void record(VkCommandBuffer cmd, vk::Image& map, uint32_t firstView, const ShadowLayout& layout,
                bool paraboloidOnly = false) const;
    // Whether light `light`'s alphaMode BLEND casters are drawn (no deep shadow map takes them).
    bool drawsBlended(uint32_t light) const;
    // Per-frame values (biases, tessellation): the sizes must not change.
    void setSettings(const ShadowSettings& settings) { settings_ = settings; }
    // Lights whose alphaMode BLEND casters go to a deep shadow map instead (src/dsm).
    void setDeepShadowLights(std::vector<uint32_t> lights) { deepShadowLights_ = std::move(lights); }

private:
    struct Pipelines {
        vk::Pipeline opaque, masked;
    };
    Pipelines make(vk::Context& ctx, vk::GraphicsDesc desc, VkDescriptorSetLayout drawLayout) const;
    void drawLight(VkCommandBuffer cmd, const Pipelines& p, const gpu::ShadowDrawPush& push, uint32_t instances,
                   bool blended) const;

    const SceneGpu& scene_;
    ShadowSettings settings_;
    Pipelines layered_, paraboloid_;
    std::vector<uint32_t> deepShadowLights_;
};

}  // namespace penumbra
