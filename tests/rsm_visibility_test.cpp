// RSM visibility (--rsm-visibility voxels and views): the exact gather against the same sum with every
// VPL-receiver pair's visibility traced by Embree, and the sampled gather against the exact one.
#include <algorithm>
#include <cmath>
#include <vector>

#include "reference/ray_scene.h"
#include "rsm_frame.h"

using namespace penumbra;
using namespace penumbra::test;
using namespace penumbra::test::rsm;

namespace {

// The exact gather (every texel) with a visibility test, against the same sum in double precision with
// the visibility of each VPL-receiver pair traced by Embree (the path tracer's BVH of the triangles).
struct TracedVisibility {
    double l1, bias;  // the GPU's sum against the traced sum: rel L1, energy bias
    double l1None;    // the sum without visibility against the traced sum
};

TracedVisibility againstTracedVisibility(vk::Context& ctx, const Scene& scene, const char* name,
                                         const RenderSettings& s) {
    TestRenderer r(ctx, scene, s);
    r.render(scene.cameras[0]);
    const Frame f = readFrame(r);
    const reference::RayScene rays(scene);
    const double eps = 1e-4 * scene.bounds.radius();
    double errGpu = 0.0, errNone = 0.0, sumTraced = 0.0, sumGpu = 0.0;
    for (size_t i = 0; i < f.position.size(); ++i) {
        if (f.normal[i] == dvec3(0.0)) continue;
        const dvec3 x = f.position[i], n = f.normal[i];
        dvec3 traced(0.0), none(0.0);
        for (const Vpl& p : f.vpls) {
            const dvec3 v = x - p.position;
            const double d2 = std::max(glm::dot(v, v), p.footprint);
            const dvec3 e = p.flux * (std::max(glm::dot(p.normal, v), 0.0) * std::max(glm::dot(n, -v), 0.0) /
                                      (d2 * d2) / kPi);
            if (e == dvec3(0.0)) continue;
            none += e;
            const dvec3 from = x + 10.0 * eps * n, to = p.position + 10.0 * eps * p.normal;
            const double len = glm::length(to - from);
            if (!rays.intersect(glm::vec3(from), glm::vec3((to - from) / len), float(eps), float(len - eps),
                                {0, -1, true}))
                traced += e;
        }
        const double gpu = luminance(f.gpuIrradiance[i]);
        errGpu += std::abs(gpu - luminance(traced));
        errNone += std::abs(luminance(none) - luminance(traced));
        sumTraced += luminance(traced);
        sumGpu += gpu;
    }
    EXPECT_GT(sumTraced, 0.0) << name;
    return {errGpu / sumTraced, sumGpu / sumTraced - 1.0, errNone / sumTraced};
}

TracedVisibility againstTracedVisibility(vk::Context& ctx, const char* name, const RenderSettings& s) {
    return againstTracedVisibility(ctx, makeBuiltinScene(name), name, s);
}

// Sponza's trouble in small: a sunlit yard beside a gallery whose upper floor is a slab 0.3 m thick. The
// wall at the back of the gallery faces the yard above and below the slab; the yard's light reaches its
// upper half only through the slab, unless visibility stops it.
Scene makeGallery() {
    Scene s;
    s.name = "gallery";
    const uint32_t grey = addMaterial(s, glm::vec3(0.6f));
    addQuad(s, {-8, 0, -4}, {0, 0, 8}, {12, 0, 0}, addMaterial(s, {0.7f, 0.6f, 0.4f}));  // the yard and the gallery, +y
    addBox(s, {2.0f, 2.15f, 0.0f}, {2.0f, 0.15f, 4.0f}, 0.0f, grey);                     // the upper floor
    addBox(s, {4.25f, 3.0f, 0.0f}, {0.25f, 3.0f, 4.0f}, 0.0f, addMaterial(s, {0.3f, 0.5f, 0.7f}));  // back wall
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.35f, -1.0f, 0.15f));
    sun.intensity = 4.0f;
    s.lights.push_back(sun);
    Camera cam;
    cam.eye = {-7.0f, 3.0f, 6.0f};
    cam.target = {3.0f, 2.0f, 0.0f};
    cam.fovy = glm::radians(60.0f);
    s.cameras.push_back(cam);
    s.computeBounds();
    return s;
}

}  // namespace

// --rsm-visibility voxels: a VPL counts only where the segment to the receiver crosses no occupied voxel.
TEST_F(RsmTest, VoxelVisibilityAgreesWithRayTracedVisibility) {
    for (const char* name : {"cornell", "street", "room"}) {
        RenderSettings s = exactIndirect(64, 48, 16);  // 16^2 VPLs a layer: lavapipe's loop budget (occupancy.glsl)
        s.rsm.visibility = RsmVisibility::Voxels;
        const TracedVisibility v = againstTracedVisibility(ctx(), name, s);
        std::printf("[ rsm ] %s: voxel visibility against traced rel L1 %.3f, bias %+.1f%%; without visibility %.3f\n",
                    name, v.l1, 100.0 * v.bias, v.l1None);
        // Measured 0.017, 0.036, 0.007 at 128 voxels (0.167, 0.103, 0.039 without visibility): within
        // 5% of the traced sum, and closer to it than no visibility at all.
        EXPECT_LT(v.l1, 0.05) << name;
        EXPECT_LT(v.l1, v.l1None) << name;
    }
}

// --rsm-visibility views (the default): a point of the segment is solid where both the RSM's and the
// camera's depth hide it. Air in the street's shadow is seen by the camera, so the sunlit street keeps
// its light; between cornell's boxes and the walls the light they block goes.
TEST_F(RsmTest, ViewsVisibilityAgreesWithRayTracedVisibility) {
    for (const char* name : {"cornell", "street", "room"}) {
        RenderSettings s = exactIndirect(64, 48, 32);
        s.rsm.visibility = RsmVisibility::Views;
        const TracedVisibility v = againstTracedVisibility(ctx(), name, s);
        std::printf("[ rsm ] %s: views visibility against traced rel L1 %.3f, bias %+.1f%%; without visibility %.3f\n",
                    name, v.l1, 100.0 * v.bias, v.l1None);
        // Measured 0.065 / +5.5%, 0.048 / +0.5%, 0.030 / +2.8% at RSM 32^2, 3 points (0.182, 0.089, 0.039
        // without visibility; 4 points: 0.054, 0.048, 0.028): coarser than voxels, closer than none.
        EXPECT_LT(v.l1, 0.09) << name;
        EXPECT_LT(std::abs(v.bias), 0.08) << name;
        EXPECT_LT(v.l1, v.l1None) << name;
    }
}

// Views visibility against the slab of makeGallery, the light through floors that made Sponza's RSM 40%
// too bright: the exact gather against the traced sum. Both views hide only the slab itself here (the
// camera sees the air under it), so a segment's points must land inside it: the error falls with their
// number and reaches the traced sum's, which shows that the two views' verdict is right and that what
// the default's 3 points miss is thin occluders between them.
TEST_F(RsmTest, ViewsVisibilityStopsLightThroughAFloorSlab) {
    RenderSettings s = exactIndirect(64, 48, 64);
    s.rsm.visibility = RsmVisibility::Views;
    std::vector<TracedVisibility> byPoints;
    for (uint32_t points : {1u, 3u, 16u}) {
        s.rsm.visibilityPoints = points;
        byPoints.push_back(againstTracedVisibility(ctx(), makeGallery(), "gallery", s));
        std::printf("[ rsm ] gallery, %u points: views visibility against traced rel L1 %.3f, bias %+.1f%%; "
                    "without visibility %.3f\n",
                    points, byPoints.back().l1, 100.0 * byPoints.back().bias, byPoints.back().l1None);
    }
    // Measured 0.337, 0.230 and 0.031 (+2.2%) against 0.391 without visibility (8 points: 0.077).
    EXPECT_LT(byPoints[0].l1, byPoints[0].l1None);
    EXPECT_LT(byPoints[1].l1, 0.7 * byPoints[1].l1None);
    EXPECT_LT(byPoints[2].l1, 0.06);
    EXPECT_LT(std::abs(byPoints[2].bias), 0.05);
    EXPECT_LT(byPoints[2].l1, byPoints[1].l1);
    EXPECT_LT(byPoints[1].l1, byPoints[0].l1);
}

// The sampled gather with voxel visibility converges to the exact gather with it: over the image,
// its mean is the exact sum's (every VPL through the same occupancy volume) when every sample walks
// the volume. With 16 walking and scaling the rest by their visible share, the ratio estimate is
// consistent but not unbiased: measured +5.0% (bound 8%).
TEST_F(RsmTest, SampledVoxelVisibilityMatchesTheExactGatherOnAverage) {
    auto meanIrradiance = [&](const RsmSettings& rsm) {
        double sum = 0.0;
        renderCornell(48, 36, rsm, Aov::Indirect, [&](TestRenderer& r) {
            const Frame f = readFrame(r);
            for (size_t i = 0; i < f.position.size(); ++i)
                if (f.normal[i] != dvec3(0.0)) sum += luminance(f.gpuIrradiance[i]);
        });
        return sum;
    };
    RsmSettings rsm;
    rsm.resolution = 32;
    rsm.visibility = RsmVisibility::Voxels;
    rsm.mode = RsmMode::AllTexels;
    const double exact = meanIrradiance(rsm);
    rsm.mode = RsmMode::Full;
    for (uint32_t rays : {400u, 16u}) {
        rsm.visibilityRays = rays;
        const double bias = meanIrradiance(rsm) / exact - 1.0;
        std::printf("[ rsm ] voxel visibility, %u of 400 samples walked: mean against the exact gather %+.2f%%\n",
                    rays, 100.0 * bias);
        EXPECT_LT(std::abs(bias), rays == 400u ? 0.03 : 0.08) << rays << " rays";
    }
}
