// Shadow maps (seed 004 and its family): the depth of every shadowed light in one array image
// (shadow.map: D32_SFLOAT, or R32_SFLOAT when the compute rasterizer draws every layer), moments
// for VSM/EVSM/MSM (shadow.moments, shadow.blur, compute), and the per-pixel filtered visibility
// of every shadowed light (shadow.filter, compute) that the lighting pass reads. Layers: cascades for directional lights (refit to the camera every frame),
// one perspective layer per spot light, 6 cube faces or 2 paraboloid hemispheres per point light.
// Bias: constant + slope-scaled rasterizer bias at render time, normal offset at lookup time.
// ShadowSettings::raster picks who draws the depth: the hardware (shadow.map) or the compute
// rasterizer (shadow.raster.*, src/raster) for all but paraboloid lights.
#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "core/depth_raster.h"
#include "core/frame_graph.h"
#include "core/scene_gpu.h"
#include "shadow/shadow_filter.h"
#include "shadow/shadow_layout.h"
#include "shadow/shadow_moments.h"
#include "shadow/shadow_raster.h"
#include "shadow/shadow_settings.h"

namespace penumbra {

class ShadowMapPass {
public:
    ShadowMapPass(vk::Allocator& alloc, SceneGpu& scene, const ShadowSettings& settings,
                  VkDescriptorSetLayout drawLayout);

    // Gives every shadow-casting light its layers; fixes the images' sizes.
    void assign(const std::vector<Light>& lights);
    // Per frame, before the views buffer is written: takes the lights' new positions, directions and
    // intensities (the same lights as assign()'s, else call assign), refits the cascades to the camera
    // (aspect = width / height, cameraFar = the camera's far plane) and writes the shaders' tables
    // into the copies of frame slot `slot`.
    void update(const std::vector<Light>& lights, const Camera& camera, float aspect, float cameraFar, uint32_t slot,
                uint32_t cascadeSnapTexels = 1);
    // Per-frame values (biases, filter radii, cascade splits); the sizes and filter kinds must not change.
    void setSettings(const ShadowSettings& settings);
    // New filter kinds (settings or the lights' own): the layout is assigned again in place; only the
    // moment images change size, the depth map and the tables stay.
    void setFilters(const ShadowSettings& settings, const std::vector<Light>& lights);

    // The shadow layers, in array-layer order; layer k is row firstView + k of the views buffer.
    const std::vector<ShadowLayer>& layers() const { return layout_.layers(); }
    const ShadowLayout& layout() const { return layout_; }
    // The shadow fields of light `light`'s GpuLight: shadow index (or NO_SHADOW) and its first layer.
    void fillGpuLight(uint32_t light, gpu::GpuLight& g) const;

    // shadow.map (layer k drawn with row firstView + k of "views"), then shadow.moments + shadow.blur
    // when a light uses a moment filter. Publishes "shadow.map", "shadow.moments", "shadow.layers",
    // "shadow.lights", "shadow.params". `extraCasters` adds other modules' passes (hair, src/dsm) into
    // "shadow.map" after shadow.map, before the moments are taken from it.
    void addTo(FrameGraph& graph, uint32_t firstView, const std::function<void(FrameGraph&)>& extraCasters = {});
    // This frame's layers that an RSM is resolved from (src/rsm), in the order of the ID image's layers:
    // addTo draws them with depth and visibility IDs ("shadow.ids", R32_UINT, one layer each; the
    // hardware's depth + colour pass or the compute rasterizer's 64-bit depth << 32 | ID) and forgets
    // the request; every other layer stays depth only.
    void requestIds(std::vector<uint32_t> layers) { idLayers_ = std::move(layers); }
    // Whether other modules rasterize casters into "shadow.map" (hair, src/dsm): the map then stays
    // D32_SFLOAT under the compute rasterizer too. Takes effect at the next assign().
    void setHardwareCasters(bool hardware) { hardwareCasters_ = hardware; }
    // Lights with a deep shadow map: their alphaMode BLEND casters stay out of the shadow map.
    void setDeepShadowLights(std::vector<uint32_t> lights) {
        raster_.setDeepShadowLights(std::move(lights));
        invalidate();
    }
    // Cached layers (both rasterizers): a layer is drawn again only when its projection changed (a
    // cascade's snapped origin, the light, the depth range), after invalidate() (casters moved, or a
    // cold frame: bench) or a bias change.
    void invalidate() {
        held_.clear();
        heldIds_.clear();
    }
    // Layers drawn by the last addTo (tests, bench).
    uint32_t layersDrawn() const { return layersDrawn_; }
    // shadow.filter: reads the G-buffer, publishes "shadow.mask".
    void addFilterTo(FrameGraph& graph);

    vk::Image& shadowMap() { return map_; }  // D32_SFLOAT or R32_SFLOAT array, one layer per ShadowLayer
    vk::Image& ids() { return ids_; }                // R32_UINT array, the last requested ID layers
    vk::Image& mask() { return filter_.mask(); }     // RG16F array, one layer per shadowed light
    vk::Image& moments() { return moments_.moments(); }
    // The compute rasterizer when it draws this pass's layers (null: the hardware does).
    const DepthRaster* computeRaster() const { return compute_.get(); }
    const ShadowSettings& settings() const { return settings_; }

private:
    vk::Allocator& alloc_;
    SceneGpu& scene_;
    ShadowSettings settings_;
    ShadowLayout layout_;
    std::vector<Light> lights_;
    ShadowRaster raster_;
    bool useCompute_;
    bool hardwareCasters_ = false;
    std::unique_ptr<DepthRaster> compute_;
    uint32_t slot_ = 0;
    ShadowMoments moments_;
    ShadowFilterPass filter_;
    vk::Image map_, ids_;
    std::vector<uint32_t> idLayers_;
    std::vector<gpu::GpuShadowLayer> held_;  // the table rows the map's layers were drawn with
    std::vector<uint32_t> heldIds_;          // the layers the ID image holds, in its layer order
    std::vector<bool> dirty_;                // this frame: layer k must be drawn
    uint32_t layersDrawn_ = 0;
    vk::BufferRing layerTable_, lightTable_, params_;

    std::vector<RasterViews> computeViews(uint32_t firstView) const;
    void addIdPass(FrameGraph& graph, ImageHandle map, uint32_t firstView);
    ImageHandle importIds(FrameGraph& graph);
    bool hasParaboloid() const;
};

}  // namespace penumbra
