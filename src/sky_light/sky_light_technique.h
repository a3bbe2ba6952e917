// The sky-light module: the irradiance each camera pixel receives from the part of the sky it sees
// (names::kSkyIrradiance), which the lighting adds to the direct light. It runs while the lighting
// module publishes an enabled sky (names::kSkyLight). Its visibility comes from depth maps (the
// default) or from rays through the voxels:
//   sky.maps.*  the scene's depth seen from each of --sky-maps directions over the upper hemisphere,
//               drawn by the compute rasterizer (core/depth_raster.h) once, and again when casters move
//   sky.look    at one pixel of each --sky-trace-step block, the share of the sky's radiance that its
//               lit directions give, per channel (sky_light/maps.comp)
//   sky.trace   a few rays from one pixel of each --sky-trace-step block through the occupancy volume
//               (names::kOccupancy): which of them are clear, as a bit mask (sky_light/trace.comp)
//   sky.weigh   the share of the sky's radiance, per channel, that the clear rays see (weigh.comp)
//   sky.filter  that share averaged over the traced receivers of its surface around it (filter.comp)
//   sky.upsample  at every pixel, the share of the traced receivers around it on its surface, times
//               the irradiance the open sky gives the pixel's normal (upsample.comp)
// The maps are kept until casters move; the trace while the view, the voxels and the settings stay
// as they were (geometry that moves under a still view is traced again a quarter a frame); the rest
// while the sky does too (a moving sun re-weighs the rays, it does not trace them).
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/depth_raster.h"
#include "core/names.h"
#include "core/technique.h"
#include "sky_light/sky_light_settings.h"
#include "sky_light/types.h"  // shaders/sky_light
#include "vk/pipeline.h"

namespace penumbra {

class SkyLightTechnique : public Technique {
public:
    SkyLightTechnique(const TechniqueBuild& b, const SkyLightSettings& s);
    const char* name() const override { return "sky-light"; }
    void addPasses(const FrameContext& f) override;
    // Moved geometry rebuilds the voxels (a new generation): traced again over four frames, at once
    // where a receiver changed. Cold frames trace everything.
    // Moved casters draw the maps again.
    void invalidateCaches(CacheDrop why) override {
        if (why == CacheDrop::All) cached_ = false;
        mapsDrawn_ = false;
    }
    void setSettings(const SkyLightSettings& s);
    static uint64_t bytes(uint64_t width, uint64_t height, uint32_t traceStep);
    // The maps and the rasterizer's depth buffer they are drawn in.
    static uint64_t mapBytes(uint64_t resolution, uint32_t count);
    // The map directions: spread evenly over the upper hemisphere (a spherical Fibonacci set, equal
    // solid angles), towards the sky.
    static std::vector<glm::vec3> mapDirections(uint32_t count);
    vk::Image& irradiance() { return irradiance_; }  // RGBA32F, for read-back

private:
    // What the last clear-ray masks were traced from: the same key, the same masks.
    struct TraceKey {
        glm::mat4 viewProj{0.0f};
        uint64_t occupancy = UINT64_MAX;
    };
    void makeMaps(const TechniqueBuild& b);
    void addMaps(const FrameContext& f, ImageHandle share, const gpu::SkyLightPush& push, bool lookUp);
    void addTrace(FrameGraph& graph, ImageHandle clearRays, const gpu::SkyLightPush& push);
    void addShareFilters(FrameGraph& graph, ImageHandle clearRays, ImageHandle share, ImageHandle filtered,
                         const gpu::SkyLightPush& push);
    void addUpsample(FrameGraph& graph, ImageHandle filtered, ImageHandle out, const gpu::SkyLightPush& push);
    void addImagePass(FrameGraph& graph, const char* name, vk::ComputeKernel& kernel, uint32_t inputBinding,
                      ImageHandle input, bool inputSampled, uint32_t outBinding, ImageHandle out, const vk::Image& size,
                      const gpu::SkyLightPush& push);
    gpu::SkyLightPush constants() const;

    SkyLightSettings settings_;
    vk::ComputeKernel look_, trace_, weigh_, filter_, upsample_;
    vk::Sampler point_;
    vk::Image clearRays_, share_, filtered_, irradiance_;  // the first three at the traced receivers' size
    vk::Buffer noVoxels_;  // an empty occupancy grid, bound when the volume is not built
    std::unique_ptr<DepthRaster> mapRaster_;
    vk::Image maps_;                        // R32_SFLOAT array: layer k seen from direction k
    vk::Buffer mapViews_, mapDirections_;   // mat4 rows (the rasterizer's), SkyMapDirection[] (the look-up's)
    float mapTexel_ = 0.0f;                 // world size of a map texel
    bool mapsDrawn_ = false;
    TraceKey traced_;
    uint64_t weighedSky_ = UINT64_MAX;
    uint32_t stalePhases_ = 0, nextPhase_ = 0;  // texel phases still to trace after the geometry moved
    bool cached_ = false;
};

}  // namespace penumbra
