// The frame: shadow maps -> G-buffer -> deferred lighting -> tone map, wired through a FrameGraph.
// Where the techniques go: RSM writes beside the shadow map (shadow pass), its gather and the LPV
// passes sit between the G-buffer and lighting, deep shadow maps build and resolve before lighting.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "dsm/hair_passes.h"
#include "render/gbuffer_pass.h"
#include "render/lighting_pass.h"
#include "lpv/lpv.h"
#include "rsm/rsm_gather.h"
#include "shadow/shadow_map_pass.h"

namespace penumbra {

enum class Aov {
    Direct = AOV_DIRECT,
    Albedo = AOV_ALBEDO,
    Normal = AOV_NORMAL,
    Depth = AOV_DEPTH,
    Shadow = AOV_SHADOW,
    Final = AOV_FINAL,
    Indirect = AOV_INDIRECT,
    LpvSlice = AOV_LPV_SLICE,
    GvSlice = AOV_GV_SLICE,
    Cascade = AOV_CASCADE,
    Transmittance = AOV_TRANSMITTANCE,
    DsmLists = AOV_DSM_LISTS,
};

enum class GiMode { None, Rsm, Lpv };

struct RenderSettings {
    uint32_t width = 1280;
    uint32_t height = 720;
    Aov aov = Aov::Final;
    float exposure = 1.0f;  // linear multiplier before the tone mapper
    ShadowSettings shadow;
    GiMode gi = GiMode::None;
    RsmSettings rsm;
    LpvSettings lpv;
    DsmSettings dsm;
};

class Renderer {
public:
    Renderer(vk::Context& ctx, const Scene& scene, const RenderSettings& settings);
    ~Renderer();

    // Renders one frame and waits for it; timings() then holds its per-pass GPU times.
    void render(const Camera& camera);
    const std::vector<vk::ScopeTiming>& timings() const { return timings_; }
    std::vector<float> readHdr();     // RGBA32F, row-major, top row first
    std::vector<uint8_t> readLdr();   // RGBA8 (sRGB-encoded for radiance and colour AOVs)
    std::string describePasses() const { return graph_.describe(); }
    const std::vector<PassDesc>& passes() const { return graph_.passes(); }
    // Things the user should know (e.g. lights rendered without shadows), collected once.
    const std::vector<std::string>& warnings() const { return warnings_; }
    vk::Allocator& allocator() { return alloc_; }
    const RenderSettings& settings() const { return settings_; }
    // The AOV of the next frames (it only selects what the lighting pass writes; `penumbra eval` reads
    // Final and Indirect of one renderer).
    void setAov(Aov aov) { settings_.aov = aov; }
    // Internals for tests and statistics: the G-buffer, read-backs, the last frame's constants.
    GBufferPass& gbuffer() { return *gbuffer_; }
    ShadowMapPass& shadow() { return *shadow_; }  // layers, shadow map, mask
    vk::CommandContext& commands() { return cmd_; }
    const gpu::FrameUniforms& frameUniforms() const { return frameConstants_; }
    // GI internals, for tests and statistics (null when that GI mode is off).
    RsmPass* rsm() { return rsm_.get(); }
    RsmGather* rsmGather() { return rsmGather_.get(); }
    LightPropagationVolume* lpv() { return lpv_.get(); }
    // Deep shadow maps (always present; inactive unless --shadow dsm) and the hair (null without strands).
    DeepShadowMaps& deepShadows() { return *dsm_; }
    const HairGpu* hair() const { return hair_.get(); }

private:
    void updateBuffers(const Camera& camera);
    void setupGi();
    void setupHairAndDsm();
    std::vector<HairShadowLayer> hairShadowLayers() const;
    gpu::TonemapPush tonemapParams(float zfar) const;

    vk::Context& ctx_;
    const Scene& scene_;
    RenderSettings settings_;
    vk::Allocator alloc_;
    vk::CommandContext cmd_;
    vk::GpuTimer timer_;
    std::unique_ptr<SceneGpu> sceneGpu_;
    vk::DescriptorLayout drawLayout_;
    std::unique_ptr<ShadowMapPass> shadow_;
    std::unique_ptr<GBufferPass> gbuffer_;
    std::unique_ptr<LightingPass> lighting_;
    std::unique_ptr<TonemapPass> tonemap_;
    std::unique_ptr<RsmPass> rsm_;
    std::unique_ptr<RsmGather> rsmGather_;
    std::unique_ptr<LightPropagationVolume> lpv_;
    std::unique_ptr<HairGpu> hair_;
    std::unique_ptr<HairGBufferPass> hairGBuffer_;
    std::unique_ptr<HairShadowPass> hairShadow_;
    std::unique_ptr<DeepShadowMaps> dsm_;
    vk::Image noIndirect_;  // bound in place of the indirect irradiance when GI is off
    vk::Buffer frame_, views_, lights_;
    FrameGraph graph_;
    std::vector<vk::ScopeTiming> timings_;
    std::vector<std::string> warnings_;
    float zfar_ = 1.0f;
    gpu::FrameUniforms frameConstants_{};
};

}  // namespace penumbra
