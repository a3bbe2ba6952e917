// Light propagation volumes (Kaplanyan 2009, Kaplanyan & Dachsbacher 2010), fed by the RSM:
//   lpv.downsample        RSM (2048^2) -> VPLs (512^2): brightest texel + 26-neighbourhood merge
//   lpv.inject-sky        (a sky on) sky-lit camera surfels -> VPLs after the RSM's: the sky's bounce
//   lpv.clear             zero the injection's fixed-point sums
//   lpv.inject-range      per cell and colour the largest coefficient a VPL adds: the scale of its sum
//   lpv.inject            VPLs -> light (L1 SH per colour, a trilinear splat half a cell along the
//                         normal: lpv/vpl_light.glsl) and geometry sums, 64-bit fixed point
//                         (integer atomics: the same sum in any order, lpv/fixed_point.glsl)
//   lpv.inject-camera     camera G-buffer surfels -> geometry sums
//   lpv.resolve           the sums -> light volume A and the geometry volume (floats)
//   lpv.faces             (--lpv-geometry voxels) the open share of every cell face, from "occupancy"
//   lpv.propagate[i]      6 neighbours x 5 faces, occlusion from the geometry volume (or the faces), running sum
//   lpv.gradient          (a GI history on) the change of each 8x8 block's irradiance since the kept
//                         volume of last frame: temporal gradients (core/names.h GiChange)
//   lpv.gather            per pixel irradiance from the summed volume (trilinear, cascades summed)
// Cascades: nested grids of the same resolution, each twice as coarse: fit to the scene for scenes
// under 20 m, else around the camera (snapped to whole cells). Light goes about one cell per step, so
// cascade k + 1, after half the steps, holds light that has gone beyond cascade k's reach: its running
// sum is kept in two halves, near (steps before (iterations + 1) / 2) and far (the rest). The gather
// adds every cascade's far half to the finest cascade's near half (a coarser near half only where the
// finer cascade does not hold the receiver): no light counted twice. The output is the same
// indirect-irradiance image the RSM gather produces.
#pragma once
#include <algorithm>
#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "lpv/lpv_settings.h"
#include "core/frame_graph.h"
#include "core/names.h"
#include "shared/types.h"
#include "scene/scene.h"

namespace penumbra {

// Cascade grids for a scene and a camera position (pure math, unit-tested).
std::vector<gpu::GpuLpvCascade> placeCascades(const Bounds& scene, const glm::vec3& eye, uint32_t count,
                                              uint32_t resolution);
uint32_t automaticCascadeCount(const Bounds& scene);

// Buffer sizes, shared with the device budget. A light volume: three RGBA32F SH colour planes per
// cell of every cascade (the propagation's two, and the sum is twice that); a geometry volume: one
// RGBA32F per cell; the VPL buffer: `n`^2 VPLs per RSM layer. The injection's fixed-point sums need
// no memory of their own: until the first step reads light volume A, the light's (8 bytes per
// coefficient) fill the sum buffer and the geometry's and the light's scales (44 bytes per cell) fit
// in light volume B (48 bytes per cell).
inline uint64_t lpvLightVolumeBytes(uint64_t resolution, uint64_t cascades) {
    return resolution * resolution * resolution * cascades * 3 * sizeof(glm::vec4);
}
inline uint64_t lpvGeometryVolumeBytes(uint64_t resolution, uint64_t cascades) {
    return resolution * resolution * resolution * cascades * sizeof(glm::vec4);
}
// The temporal gradients' change image (one RGBA32F texel per LPV_CHANGE_BLOCK^2 pixels) and the
// kept volume's cascade placement (one host-written copy per frame in flight); the kept light sum
// itself is a second sum buffer (2 x lpvLightVolumeBytes).
uint64_t lpvGradientBytes(uint64_t width, uint64_t height);
inline uint64_t lpvVplBytes(uint64_t n, uint64_t rsmLayers) { return std::max<uint64_t>(rsmLayers, 1) * n * n * sizeof(gpu::GpuVpl); }

class LightPropagationVolume {
public:
    LightPropagationVolume(vk::Allocator& alloc, uint32_t width, uint32_t height, const LpvSettings& settings,
                           const Bounds& sceneBounds);
    // Places the cascades around the camera for this frame.
    void update(const glm::vec3& eye);
    // Reads "frame", "lights", the G-buffer, the RSM ("rsm.*", `rsmLayers` layers) and, when
    // published, the sky's irradiance ("sky.irradiance", bounced from the camera's surfels);
    // publishes "gi.irradiance".
    // `occupancyGeneration` (OccupancyVolume::generation, --lpv-geometry voxels): the faces are made
    // again only when it or the cascades changed.
    // `accumulation` (the temporal-GI module's word; null: no history): while a history is kept, each
    // frame keeps its summed volume, and a frame that adds to the history after one that kept a
    // volume publishes "gi.change" (names::kGiChange); `slot` selects the host-written copies.
    void addTo(FrameGraph& graph, uint32_t rsmLayers, uint64_t occupancyGeneration = 0,
               const GiAccumulation* accumulation = nullptr, uint32_t slot = 0);
    // Per-frame values (occlusion, blend band, debug slice); sizes and the pass count must not change.
    void setSettings(const LpvSettings& settings);

    // Test entry: VPLs given directly (no RSM, no camera), then clear + inject + propagate only.
    void setVpls(vk::CommandContext& cmd, const std::vector<gpu::GpuVpl>& vpls);
    void addPropagationFromVpls(FrameGraph& graph);

    vk::Image& irradiance() { return irradiance_; }
    const LpvSettings& settings() const { return settings_; }
    uint32_t cascadeCount() const { return cascadeCount_; }
    const gpu::LpvPush& constants() const { return push_; }
    // Buffers for tests: the summed light volume (near half, then far half), the last step's light,
    // the geometry volume, VPLs.
    const vk::Buffer& accumulated() const { return accum_; }
    const vk::Buffer& lastStep() const { return settings_.iterations % 2 ? volumeB_ : volumeA_; }
    const vk::Buffer& geometry() const { return geometry_; }
    // The injected light (light volume A): steps 2, 4, ... write A again, so one step leaves it.
    const vk::Buffer& injected() const { return volumeA_; }
    const vk::Buffer& faces() const { return faces_; }  // --lpv-geometry voxels
    const vk::Buffer& vpls() const { return vpls_; }
    // The temporal gradients of the last frame that measured them (names::kGiChange).
    vk::Image& change() { return change_; }
    GiChange& changeTexel() { return changeTexel_; }

private:
    void addDownsample(FrameGraph& graph);
    void addInjection(FrameGraph& graph);
    void addResolve(FrameGraph& graph);
    void addCameraGeometry(FrameGraph& graph);
    void addSkySurfels(FrameGraph& graph);
    void addPropagation(FrameGraph& graph, uint64_t occupancyGeneration = 0);
    bool keepLastSum();  // swaps the sum buffers; true: the other holds a volume of the same grids
    void addGradient(FrameGraph& graph, uint32_t slot);
    void addGather(FrameGraph& graph);
    static void run(PassContext& c, const vk::ComputeKernel& kernel, const gpu::LpvPush& push, glm::uvec3 groups);

    vk::Allocator& alloc_;
    LpvSettings settings_;
    Bounds bounds_;
    uint32_t width_, height_, cascadeCount_, layers_ = 0;
    uint32_t skySurfels_ = 0;  // sky-lit camera surfels after the RSM's VPLs (lpv/inject_sky.comp)
    gpu::LpvPush push_{};
    bool voxels() const { return settings_.geometry == LpvGeometry::Voxels; }

    vk::ComputeKernel downsample_, injectRange_, inject_, injectCamera_, injectSky_, resolve_, propagate_, gather_, faceKernel_;
    vk::Sampler pointSampler_;
    vk::Buffer vpls_, volumeA_, volumeB_, accum_, geometry_;
    vk::Buffer faces_;  // --lpv-geometry voxels: per cell the open share of its -x, -y, -z faces
    std::optional<std::pair<uint64_t, std::array<gpu::GpuLpvCascade, LPV_MAX_CASCADES>>> facesOf_;  // what they show
    vk::Image irradiance_;
    // Temporal gradients (lpv/gradient.comp). The sum buffer is cleared and refilled every frame (the
    // injection's fixed-point sums live in it first), so no frame reads the last one's: a second sum
    // buffer swaps with it each frame a history is kept, and holds the last frame's sum at no copy.
    vk::ComputeKernel gradient_;
    vk::Buffer keptAccum_;
    vk::BufferRing keptCascades_;  // the kept volume's GpuLpvCascade[LPV_MAX_CASCADES] (uniform)
    vk::Image change_;
    GiChange changeTexel_{LPV_CHANGE_BLOCK};
    struct Kept {
        bool valid = false;
        uint32_t resolution = 0, cascadeCount = 0;
        std::array<gpu::GpuLpvCascade, LPV_MAX_CASCADES> cascades{};
    } kept_;  // what keptAccum_ holds
};

}  // namespace penumbra
