// The shadow depth pass: every layer of every shadowed light in one layered render-pass instance.
// One instanced draw per scene draw and light renders all of the light's layers (instance = layer):
// cascades and cube faces through shadow/shadow.vert, paraboloid hemispheres through a tessellated
// pipeline (shadow/paraboloid.*) because the paraboloid mapping bends straight edges.
// Depth only: opaque casters have no fragment shader, alpha-masked ones only discard.
#pragma once
#include <functional>
#include <vector>

#include "core/scene_gpu.h"
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
    // Only layers for which `draws(layer)` holds are cleared and drawn; the others keep their depth
    // (cached, or drawn by recordIds or the compute rasterizer). Records nothing when none is drawn.
    void record(VkCommandBuffer cmd, vk::Image& map, uint32_t firstView, const ShadowLayout& layout,
                bool paraboloidOnly, const std::function<bool(uint32_t)>& draws) const;
    // Shadow layer `layer` of light `light` (not a paraboloid one) with its depth and, in layer
    // `idLayer` of `ids` (R32_UINT), the visibility ID of every texel (core/visibility.glsl): the
    // one raster of a light view that an RSM is resolved from (src/rsm).
    void recordIds(VkCommandBuffer cmd, vk::Image& map, vk::Image& ids, uint32_t layer, uint32_t idLayer,
                   uint32_t viewRow, uint32_t light) const;
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
    void setRasterState(VkCommandBuffer cmd) const;
    Pipelines layered_, paraboloid_, ids_;
    std::vector<uint32_t> deepShadowLights_;
};

}  // namespace penumbra
