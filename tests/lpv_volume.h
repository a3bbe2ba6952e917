// The light propagation volume on its own, fed VPLs directly (no RSM, no camera): the harness of the
// LPV volume tests (tests/lpv_test.cpp, tests/lpv_stable_test.cpp).
#pragma once
#include <cstring>
#include <memory>
#include <vector>

#include "gpu_fixture.h"
#include "core/frame_graph.h"
#include "core/scene_gpu.h"
#include "lpv/lpv.h"
#include "voxel/occupancy_volume.h"

namespace penumbra::test {

struct VolumeRun {
    std::vector<glm::vec4> accum, last, geometry;
    std::vector<glm::vec4> injected;  // light volume A: the injected light while iterations == 1
    float cell;
    gpu::LpvPush push;
};

inline std::vector<glm::vec4> asVec4(const std::vector<uint8_t>& bytes) {
    std::vector<glm::vec4> v(bytes.size() / sizeof(glm::vec4));
    std::memcpy(v.data(), bytes.data(), bytes.size());
    return v;
}

inline gpu::GpuVpl vpl(const glm::vec3& p, const glm::vec3& n, const glm::vec3& flux, float area = 0.0f) {
    return {p, 1u, glm::normalize(n), area, flux, 0u};
}

// A single 32^3 grid over [-1, 1]^3 (cell 2.04 / 31), no camera.
inline Bounds unitCube() {
    Bounds b;
    b.extend({-1, -1, -1});
    b.extend({1, 1, 1});
    return b;
}

class LpvVolumeTest : public GpuTest {
protected:
    // `occluders`: blocking from their occupancy volume (--lpv-geometry voxels); without them, from the
    // geometry volume (surfels).
    VolumeRun run(const std::vector<gpu::GpuVpl>& vpls, uint32_t iterations, bool occlusion = true,
                  uint32_t resolution = 32, uint32_t cascades = 1, const Scene* occluders = nullptr) {
        vk::Allocator alloc(ctx());
        vk::CommandContext cmd(alloc);
        LpvSettings s;
        s.resolution = resolution;
        s.iterations = iterations;
        s.cascades = cascades;
        s.occlusion = occlusion;
        s.geometry = occluders ? LpvGeometry::Voxels : LpvGeometry::Surfels;  // no occupancy volume: surfels
        LightPropagationVolume lpv(alloc, 8, 8, s, unitCube());
        lpv.update(glm::vec3(0.0f));
        lpv.setVpls(cmd, vpls);
        FrameGraph graph(ctx());
        std::unique_ptr<SceneGpu> meshes;
        std::unique_ptr<OccupancyVolume> volume;
        if (occluders) {
            meshes = std::make_unique<SceneGpu>(cmd, *occluders);
            volume = std::make_unique<OccupancyVolume>(alloc, *meshes, 64);
            volume->addTo(graph);
        }
        lpv.addPropagationFromVpls(graph);
        cmd.submitAndWait([&](VkCommandBuffer c) { graph.execute(c, nullptr); });
        VolumeRun r;
        r.accum = asVec4(cmd.readBuffer(lpv.accumulated(), lpv.accumulated().size()));
        r.last = asVec4(cmd.readBuffer(lpv.lastStep(), lpv.lastStep().size()));
        r.geometry = asVec4(cmd.readBuffer(lpv.geometry(), lpv.geometry().size()));
        r.injected = asVec4(cmd.readBuffer(lpv.injected(), lpv.injected().size()));
        r.cell = lpv.constants().cascades[0].cellSize;
        r.push = lpv.constants();
        return r;
    }
};

}  // namespace penumbra::test
