// The core camera and lighting path, a module like the others: the camera's G-buffer, deferred
// lighting of the summed indirect-irradiance contributions, the debug views and the tone map.
#pragma once
#include <memory>
#include <optional>

#include "core/irradiance_sum.h"
#include "lighting/auto_exposure.h"
#include "core/names.h"
#include "core/sky.h"
#include "core/technique.h"
#include "lighting/gbuffer_pass.h"
#include "lighting/gpu_sky.h"
#include "lighting/lighting_pass.h"
#include "lighting/lighting_settings.h"

namespace penumbra {

class GpuScene;

// The G-buffer (scene.vert/gbuffer.frag, or the visibility path) of the opaque surfaces; with
// translucency off, BLEND surfaces too, and hair drawn after it into the same depth (src/dsm).
class CameraTechnique : public Technique {
public:
    explicit CameraTechnique(const TechniqueBuild& b);
    const char* name() const override { return "camera"; }
    void addPasses(const FrameContext& f) override;
    GBufferPass& gbuffer() { return gbuffer_; }

private:
    GBufferPass gbuffer_;
    vk::Image noIds_;  // bound in place of the visibility IDs on the classic G-buffer path
};

// Deferred lighting (publishes "hdr") over the sum of the frame's irradiance contributions (a black
// "gi.irradiance" when none), then the debug views and the tone mapper ("ldr"). Its update makes the
// sky for the frame's lights and publishes it (names::kSkyLight, and on the GPU names::kSkySh, whose
// passes it adds ahead of every technique's) for every technique's passes.
class LightingTechnique : public Technique {
public:
    LightingTechnique(const TechniqueBuild& b, const LightingSettings& settings);
    ~LightingTechnique() override;
    const char* name() const override { return "lighting"; }
    void setSettings(const LightingSettings& settings) { settings_ = settings; }
    void update(const FrameContext& f) override;
    void addPasses(const FrameContext& f) override;
    void addOutputPasses(const FrameContext& f) override;
    LightingPass& lighting() { return lighting_; }
    TonemapPass& tonemap() { return tonemap_; }
    AutoExposure& autoExposure() { return exposure_; }
    GpuSky& gpuSky() { return gpuSky_; }

private:
    // What the sky was made from: the settings and the first directional light (the analytic sun).
    struct SkyKey {
        SkySettings settings;
        bool hasSun = false;
        glm::vec3 sunDirection{0.0f}, sunColor{0.0f};
        float sunIntensity = 0.0f;
        bool operator==(const SkyKey&) const = default;
    };
    static SkyKey skyKey(const SkySettings& settings, const std::vector<Light>& lights);
    void refreshSky(const std::vector<Light>& lights);
    gpu::TonemapPush tonemapParams(const FrameContext& f) const;
    Blackboard& board_;
    IrradianceSum irradiance_;
    LightingPass lighting_;
    DebugViewPass debugView_;
    TonemapPass tonemap_;
    vk::Image noIndirect_;  // bound in place of the indirect irradiance when GI is off
    vk::Image noSky_;       // and of the sky's irradiance without a sky
    LightingSettings settings_;
    std::vector<std::string>& warnings_;
    // The sky of the frame's lights: an analytic one as its model (evaluated on the GPU), any
    // other as the CPU's Sky.
    Sky sky_;
    std::optional<AnalyticSkyModel> analyticSky_;
    SkyKey skyKey_;
    bool skyMade_ = false;
    SkyLight skyLight_;
    GpuSky gpuSky_;
    ImageHandle background_;  // this frame's, from the update
    AutoExposure exposure_;
    bool wasAuto_ = false;  // the last frame's exposure was auto (switching it on restarts the adaptation)
    bool gpuSkyStale_ = true;  // the sky changed since it was last given to the GPU
};

}  // namespace penumbra
