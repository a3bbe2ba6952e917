// The sky-light module: the irradiance each camera pixel receives from the part of the sky it sees
// (names::kSkyIrradiance), which the lighting adds to the direct light. It runs while the lighting
// module publishes an enabled sky (names::kSkyLight).
//   sky.trace   a few rays per pixel through the occupancy volume (names::kOccupancy): the share of
//               the sky's radiance, per channel, that reaches the receiver (sky_light/trace.comp)
//   sky.filter  that share averaged over the receiver's surface around it, times the irradiance the
//               open sky gives its normal (sky_light/filter.comp)
// Both are skipped, the last result kept, while the view, the voxels, the sky and the settings stay
// as they were.
#pragma once
#include <array>
#include <cstdint>

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
    void invalidateCaches() override { cached_ = false; }
    void setSettings(const SkyLightSettings& s);
    static uint64_t bytes(uint64_t width, uint64_t height);
    vk::Image& irradiance() { return irradiance_; }  // RGBA32F, for read-back

private:
    // What the last result was computed from: the same key, the same image.
    struct CacheKey {
        glm::mat4 viewProj{0.0f};
        uint64_t occupancy = UINT64_MAX, sky = UINT64_MAX;
        bool operator==(const CacheKey&) const = default;
    };
    void addTrace(FrameGraph& graph, ImageHandle visibility, const gpu::SkyLightPush& push);
    void addFilter(FrameGraph& graph, ImageHandle visibility, ImageHandle out, const gpu::SkyLightPush& push);
    gpu::SkyLightPush constants(const SkyLight& sky) const;

    SkyLightSettings settings_;
    vk::ComputeKernel trace_, filter_;
    vk::Sampler point_;
    vk::Image visibility_, irradiance_;
    vk::Buffer noVoxels_;  // an empty occupancy grid, bound when the volume is not built
    CacheKey key_;
    bool cached_ = false;
};

}  // namespace penumbra
