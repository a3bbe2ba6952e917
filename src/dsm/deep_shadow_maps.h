// Deep shadow maps (seed 002; Lokovic & Veach 2000; GPU Pro 4 "Real-Time Deep Shadow Maps"): the
// transmittance of semi-transparent casters (hair strands, alphaMode BLEND meshes) as a function of
// depth, per texel of a light's map, stored as linked lists built in one raster pass. Opaque casters
// stay in the ordinary shadow map; lighting multiplies both (dsm/dsm_lookup.glsl).
//
// Frame: dsm.clear -> dsm.build (raster) -> dsm.resolve -> dsm.link (compute) -> lighting.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "dsm/deep_opacity_build.h"
#include "dsm/deep_shadow_build.h"
#include "dsm/deep_shadow_resolve.h"

namespace penumbra {

// The counters of the last frame, and what the buffers cost.
struct DsmFrameStats {
    uint32_t maps = 0, resolution = 0;
    uint64_t fragments = 0;        // light-space fragments of translucent casters (allocation attempts)
    uint64_t hidden = 0;           // fragments the depth test skipped (behind the opaque casters)
    uint64_t capacity = 0;         // nodes in the pool
    bool deviceLimited = false;    // the pool is the largest the device addresses
    uint64_t overflow = 0;         // fragments dropped because the pool was full
    uint64_t kept = 0;             // nodes in the resolved lists
    uint64_t beyondMaxList = 0;    // nodes dropped by the per-texel cap (the farthest of long lists)
    uint64_t sorted = 0;           // nodes the resolve sorted (the rest lay in depth buckets behind the cap's)
    uint32_t maxList = 0, longest = 0;
    uint64_t lists = 0;            // texels with at least one node
    uint64_t poolBytes = 0, headBytes = 0, usedBytes = 0;
    float opacityLayer = 0.0f;     // deep opacity maps: their layer thickness (then no list counts)
};

class DeepShadowMaps {
public:
    // Gives a DSM to the lights `settings` selects (directional and spot: one map; point: a cube of six).
    // Throws on bad settings (light index, pool size beyond the device). `computeHair`: hair is
    // rasterized in compute (DeepShadowBuildPass).
    DeepShadowMaps(vk::Allocator& alloc, SceneGpu& scene, const HairGpu* hair, const DsmSettings& settings,
                   uint32_t shadowResolution, const std::vector<Light>& lights, std::vector<std::string>& warnings,
                   bool computeHair = false);

    bool active() const { return !res_->layers.empty(); }
    // Per frame: refits each DSM to its light's current position and direction (same lights as built).
    void update(const std::vector<Light>& lights, const Bounds& sceneBounds, uint32_t slot);
    // Whether light `light` has a DSM: its translucent casters then stay out of its ordinary map.
    bool covers(uint32_t light) const;
    // The build and resolve passes (when active), and the lookup's inputs by name (placeholders when
    // inactive): "dsm.lights", "dsm.heads", "dsm.nodes", "dsm.side".
    void addTo(FrameGraph& graph);

    DsmFrameStats readStats(vk::CommandContext& cmd) const;
    const DsmResources& resources() const { return *res_; }
    const DsmSettings& settings() const { return settings_; }

private:
    DsmSettings settings_;
    std::unique_ptr<DsmResources> res_;
    std::unique_ptr<DeepShadowBuildPass> build_;
    std::unique_ptr<DeepShadowResolvePass> resolve_;
    std::unique_ptr<DeepOpacityBuildPass> opacity_;  // `--shadow dom`, in place of the two above
};

// One report line ("dsm: ..."), and the warnings a frame deserves (pool overflow).
std::string describeDsm(const DsmFrameStats& s);
std::vector<std::string> dsmWarnings(const DsmFrameStats& s);

}  // namespace penumbra
