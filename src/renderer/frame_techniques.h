// The techniques of penumbra's frame, each behind the Technique interface: camera (G-buffer and
// hair), shadow maps (with hair as a caster), deep shadow maps, reflective shadow maps with their
// gather, light propagation volumes, and lighting with tone mapping. Renderer builds them per
// settings over one long-lived GpuScene and rebuilds only those a settings change invalidates.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "dsm/deep_shadow_maps.h"
#include "dsm/hair_passes.h"
#include "dsm/translucency.h"
#include "lpv/lpv.h"
#include "lighting/gbuffer_pass.h"
#include "core/gpu_scene.h"
#include "temporal_gi/gi_history.h"
#include "lighting/lighting_pass.h"
#include "core/technique.h"
#include "rsm/rsm_flux.h"
#include "rsm/rsm_gather.h"
#include "shadow/shadow_map_pass.h"
#include "voxel/occupancy_volume.h"

namespace penumbra {

// G-buffer (scene.vert/gbuffer.frag) of the opaque surfaces; hair and BLEND surfaces either into
// per-pixel translucency lists (composited after lighting: addCompositeTo) or, with
// `--translucency off`, opaque into the G-buffer.
class CameraTechnique : public Technique {
public:
    CameraTechnique(vk::Allocator& alloc, GpuScene& scene, const RenderSettings& s, VkDescriptorSetLayout drawLayout);
    const char* name() const override { return "camera"; }
    void addPasses(const FrameContext& f) override;
    // The translucency composite over "hdr" (LightingTechnique calls it after the lighting pass).
    void addCompositeTo(FrameGraph& graph) {
        if (translucency_) translucency_->addCompositeTo(graph);
    }
    GBufferPass& gbuffer() { return gbuffer_; }
    const CameraTranslucency* translucency() const { return translucency_.get(); }

private:
    GBufferPass gbuffer_;
    std::unique_ptr<HairGBufferPass> hair_;
    std::unique_ptr<CameraTranslucency> translucency_;
};

class ShadowTechnique : public Technique {
public:
    // `coveredByDsm(light)`: whether a deep shadow map takes that light's translucent casters.
    ShadowTechnique(vk::Allocator& alloc, GpuScene& scene, const RenderSettings& s, VkDescriptorSetLayout drawLayout,
                    const std::vector<Light>& lights, std::function<bool(uint32_t)> coveredByDsm,
                    std::vector<std::string>& warnings);
    const char* name() const override { return "shadow"; }
    void update(const FrameContext& f) override;
    void addPasses(const FrameContext& f) override;
    void applyPerFrame(const RenderSettings& s) override;
    void setFilters(const RenderSettings& s, const std::vector<Light>& lights) { pass_.setFilters(s.shadow, lights); }
    ShadowMapPass& pass() { return pass_; }

private:
    std::vector<HairShadowLayer> hairLayers(const std::vector<Light>& lights) const;
    ShadowMapPass pass_;
    std::function<bool(uint32_t)> coveredByDsm_;
    std::unique_ptr<HairShadowPass> hair_;
    const HairGpu* hairGpu_;
};

class DsmTechnique : public Technique {
public:
    DsmTechnique(vk::Allocator& alloc, GpuScene& scene, const RenderSettings& s, const std::vector<Light>& lights,
                 std::vector<std::string>& warnings);
    const char* name() const override { return "dsm"; }
    void update(const FrameContext& f) override { maps_.update(f.lights, bounds_, f.slot); }
    void addPasses(const FrameContext& f) override { maps_.addTo(f.graph); }
    DeepShadowMaps& maps() { return maps_; }

private:
    DeepShadowMaps maps_;
    Bounds bounds_;
};

// The RSM of every shadowed light, rendered with the shadow layers' projections; with `gather`
// (GI rsm) also the indirect light from it, without (GI lpv) only the RSM for injection.
class RsmTechnique : public Technique {
public:
    RsmTechnique(vk::Allocator& alloc, vk::CommandContext& cmd, GpuScene& scene, const RenderSettings& s,
                 ShadowMapPass& shadow, bool gather);
    const char* name() const override { return "rsm"; }
    void update(const FrameContext& f) override;
    void addPasses(const FrameContext& f) override;
    void applyPerFrame(const RenderSettings& s) override;
    RsmPass& pass() { return pass_; }
    RsmGather* gather() { return gather_.get(); }
    RsmFluxSampler* flux() { return flux_.get(); }
    OccupancyVolume* occupancy() { return occupancy_.get(); }
    // Instances moved: the occupancy volume is voxelized again.
    void invalidate() {
        if (occupancy_) occupancy_->invalidate();
    }

private:
    ShadowMapPass& shadow_;
    bool widestCascadeOnly_;
    RsmPass pass_;
    std::unique_ptr<OccupancyVolume> occupancy_;  // --rsm-visibility voxels
    std::unique_ptr<RsmFluxSampler> flux_;  // --rsm-far flux
    std::unique_ptr<RsmGather> gather_;
};

class LpvTechnique : public Technique {
public:
    // `occupancy`: the RSM technique's (--lpv-geometry voxels), or null.
    LpvTechnique(vk::Allocator& alloc, const Bounds& bounds, const RenderSettings& s, RsmPass& rsm,
                 const OccupancyVolume* occupancy);
    const char* name() const override { return "lpv"; }
    void addPasses(const FrameContext& f) override;
    void applyPerFrame(const RenderSettings& s) override { volume_.setSettings(s.lpv); }
    LightPropagationVolume& volume() { return volume_; }

private:
    RsmPass& rsm_;
    const OccupancyVolume* occupancy_;
    LightPropagationVolume volume_;
};

// Deferred lighting and tone mapping; publishes a black "gi.irradiance" when no GI technique did.
class LightingTechnique : public Technique {
public:
    // `afterLighting` adds passes that rewrite "hdr" before the debug views and the tone mapper.
    LightingTechnique(vk::Allocator& alloc, vk::CommandContext& cmd, const RenderSettings& s,
                      std::function<void(FrameGraph&)> afterLighting = {});
    const char* name() const override { return "lighting"; }
    void addPasses(const FrameContext& f) override;
    LightingPass& lighting() { return lighting_; }
    TonemapPass& tonemap() { return tonemap_; }
    // The GI that feeds the temporal accumulation changed: start it anew.
    void resetHistory() {
        if (history_) history_->reset();
    }
    void applyPerFrame(const RenderSettings& s) override { historyAlpha_ = s.giTemporalAlpha; }

private:
    gpu::TonemapPush tonemapParams(const RenderSettings& s, float depthFar) const;
    LightingPass lighting_;
    std::function<void(FrameGraph&)> afterLighting_;
    DebugViewPass debugView_;
    TonemapPass tonemap_;
    vk::Image noIndirect_;  // bound in place of the indirect irradiance when GI is off
    vk::Image noIds_;       // bound in place of the visibility IDs on the classic G-buffer path
    std::unique_ptr<GiHistory> history_;  // --gi-temporal
    float historyAlpha_ = 0.1f;
};

}  // namespace penumbra
