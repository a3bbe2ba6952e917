// Which shadow layers exist and what each one sees: one layer per spot light, `cascades.count`
// per directional light (refit to the camera every frame), 6 cube faces or 2 paraboloid hemispheres
// per point light, all in one D32 array image. Pure CPU (no Vulkan), unit-tested; it also builds
// the tables the shaders read (shared/types.h: GpuShadowLight, GpuShadowLayer, GpuShadowParams).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "shadow/shadow_settings.h"
#include "shared/types.h"

namespace penumbra {

// One layer of the shadow-map array. Other passes that render "per shadow layer" (reflective
// shadow maps) use `projection` as is; paraboloid layers have no matrix projection (see
// LightProjection) and are better skipped by them.
struct ShadowLayer {
    uint32_t light = 0;     // index into the scene's lights
    uint32_t index = 0;     // cascade (directional), cube face +x,-x,+y,-y,+z,-z, hemisphere (0 = +axis)
    LightProjection projection;
    float splitNear = 0.0f, splitFar = 0.0f;  // cascades: the camera view depths it serves
};

// One shadowed light and its run of layers.
struct ShadowedLight {
    uint32_t light = 0;
    uint32_t firstLayer = 0, layerCount = 0;
    uint32_t kind = SHADOW_KIND_SINGLE;  // SHADOW_KIND_*
    ShadowFilter filter = ShadowFilter::Hard;
};

class ShadowLayout {
public:
    ShadowLayout(const ShadowSettings& settings, const Bounds& sceneBounds);

    // Fixes the layers of every shadowed light (`castsShadow`); their projections are computed by update().
    void assign(const std::vector<Light>& lights);
    // Recomputes every projection; the cascades follow the camera (aspect = width / height,
    // cameraFar = the view's far plane).
    // `cascadeSnapTexels`: cascades move in steps of that many texels (fitCascades).
    void update(const std::vector<Light>& lights, const Camera& camera, float aspect, float cameraFar,
                uint32_t cascadeSnapTexels = 1);

    // Per-frame values only (radii, splits); what assign() sized must stay as it was.
    void setSettings(const ShadowSettings& settings) { settings_ = settings; }

    const std::vector<ShadowLayer>& layers() const { return layers_; }
    const std::vector<ShadowedLight>& shadowed() const { return shadowed_; }
    int shadowIndexOf(uint32_t light) const { return light < indexOfLight_.size() ? indexOfLight_[light] : -1; }
    uint32_t momentLayerCount() const { return momentLayers_; }
    // Texels kept outside the region a layer of a light with this filter must cover: the filter's
    // reach from a covered point plus the bilinear footprint, so that taps near the border read depth.
    float marginTexels(ShadowFilter filter) const;

    std::vector<gpu::GpuShadowLight> gpuLights() const;
    std::vector<gpu::GpuShadowLayer> gpuLayers() const;
    gpu::GpuShadowParams gpuParams() const;

private:
    ShadowSettings settings_;
    Bounds bounds_;
    std::vector<ShadowLayer> layers_;
    std::vector<ShadowedLight> shadowed_;
    std::vector<int> indexOfLight_;
    std::vector<uint32_t> momentLayerOf_;  // per layer, SHADOW_NO_MOMENTS when its light is not filtered by moments
    uint32_t momentLayers_ = 0;
};

bool usesMoments(ShadowFilter filter);

}  // namespace penumbra
