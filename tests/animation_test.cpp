// Motion: glTF animation sampling against hand-computed values, the node hierarchy kept
// through loading (1000 deep, walked without recursion), instancing (a mesh drawn by two nodes is
// stored once), an animated occluder whose hard shadow lands where the animation puts it at two
// times, and a sequence that uploads geometry once.
#include <map>

#include <glm/gtc/constants.hpp>

#include "motion_test_util.h"
#include "scene/animation.h"
#include "scene/motion.h"

namespace penumbra::test {
namespace {

AnimationChannel channel(AnimationPath path, Interpolation interp, std::vector<float> times,
                         std::vector<glm::vec4> values) {
    AnimationChannel c;
    c.path = path;
    c.interpolation = interp;
    c.times = std::move(times);
    c.values = std::move(values);
    return c;
}

TEST(AnimationSampling, StepHoldsEachKeyUntilTheNext) {
    const auto c = channel(AnimationPath::Translation, Interpolation::Step, {0, 1, 2},
                           {glm::vec4(1, 0, 0, 0), glm::vec4(2, 0, 0, 0), glm::vec4(3, 0, 0, 0)});
    EXPECT_EQ(sampleChannel(c, 0.99f).x, 1.0f);
    EXPECT_EQ(sampleChannel(c, 1.0f).x, 2.0f);
    EXPECT_EQ(sampleChannel(c, 1.5f).x, 2.0f);
    EXPECT_EQ(sampleChannel(c, 7.0f).x, 3.0f);   // after the last key: the last value
    EXPECT_EQ(sampleChannel(c, -1.0f).x, 1.0f);  // before the first: the first
}

TEST(AnimationSampling, LinearTranslation) {
    const auto c = channel(AnimationPath::Translation, Interpolation::Linear, {1, 3},
                           {glm::vec4(0, 0, 0, 0), glm::vec4(4, 8, -4, 0)});
    const glm::vec4 v = sampleChannel(c, 1.5f);  // a quarter of the way
    EXPECT_FLOAT_EQ(v.x, 1.0f);
    EXPECT_FLOAT_EQ(v.y, 2.0f);
    EXPECT_FLOAT_EQ(v.z, -1.0f);
}

TEST(AnimationSampling, LinearRotationIsAShorterArcSlerp) {
    const float s45 = std::sin(glm::radians(45.0f)), c45 = std::cos(glm::radians(45.0f));
    const float s225 = std::sin(glm::radians(22.5f)), c225 = std::cos(glm::radians(22.5f));
    // Identity to 90 degrees about +Y; half way is 45 degrees: (0, sin 22.5, 0, cos 22.5).
    for (float sign : {1.0f, -1.0f}) {  // -q is the same rotation: slerp must take the shorter arc
        const auto c = channel(AnimationPath::Rotation, Interpolation::Linear, {0, 1},
                               {glm::vec4(0, 0, 0, 1), sign * glm::vec4(0, s45, 0, c45)});
        const glm::vec4 q = sampleChannel(c, 0.5f);
        EXPECT_NEAR(q.x, 0.0f, 1e-6f);
        EXPECT_NEAR(q.y, s225, 1e-6f);
        EXPECT_NEAR(q.z, 0.0f, 1e-6f);
        EXPECT_NEAR(q.w, c225, 1e-6f);
        // A quarter: 22.5 degrees, not the normalized lerp's angle.
        const glm::vec4 q4 = sampleChannel(c, 0.25f);
        EXPECT_NEAR(q4.y, std::sin(glm::radians(11.25f)), 1e-6f);
    }
}

TEST(AnimationSampling, CubicSplineScalesTangentsByTheKeyInterval) {
    // Keys at t = 0 and 2 (interval 2): v0 = 0 with out-tangent 1, v1 = 1 with in-tangent 0. At
    // u = 0.5: (u^3 - 2u^2 + u) * 2 * 1 + (-2u^3 + 3u^2) * 1 = 0.125 * 2 + 0.5 = 0.75 (0.625 without
    // the interval).
    const auto c = channel(AnimationPath::Translation, Interpolation::CubicSpline, {0, 2},
                           {glm::vec4(9), glm::vec4(0), glm::vec4(1, 0, 0, 0),    // in, value, out of key 0
                            glm::vec4(0), glm::vec4(1, 0, 0, 0), glm::vec4(9)});  // of key 1
    EXPECT_NEAR(sampleChannel(c, 1.0f).x, 0.75f, 1e-6f);
    EXPECT_NEAR(sampleChannel(c, 0.0f).x, 0.0f, 1e-6f);
    EXPECT_NEAR(sampleChannel(c, 2.0f).x, 1.0f, 1e-6f);
    // u = 0.25: (0.015625 - 0.125 + 0.25) * 2 + (-0.03125 + 0.1875) = 0.28125 + 0.15625 = 0.4375
    EXPECT_NEAR(sampleChannel(c, 0.5f).x, 0.4375f, 1e-6f);
}

TEST(AnimationSampling, LoopsByDefaultAndClampHoldsTheEnd) {
    Animation a;
    a.duration = 2.0f;
    EXPECT_FLOAT_EQ(animationLocalTime(a, 5.0, false), 1.0f);
    EXPECT_FLOAT_EQ(animationLocalTime(a, 5.0, true), 2.0f);
    EXPECT_FLOAT_EQ(animationLocalTime(a, 0.5, true), 0.5f);
}

// ---- glTF files written by the tests ----

TEST(SceneGraph, HierarchyOf1000NodesIsKeptAndAnimatedFromItsRoot) {
    TempDir dir;
    QuadFile f;
    const int times = f.addFloats({0.0f, 2.0f}, "SCALAR", 2);
    const int values = f.addFloats({0.0f, 0.0f, 0.0f, 4.0f, 0.0f, 0.0f}, "VEC3", 2);
    json nodes = json::array();
    for (int i = 0; i < 1000; ++i) {
        json n{{"translation", {0, 0.001, 0}}};
        if (i + 1 < 1000) n["children"] = {i + 1};
        else n["mesh"] = 1;
        nodes.push_back(n);
    }
    f.doc["nodes"] = nodes;
    f.doc["scenes"] = {{{"nodes", {0}}}};
    f.doc["animations"] = {{{"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}},
                            {"samplers", {{{"input", times}, {"output", values}}}}}};
    const Scene s = loadScene(f.write(dir));
    ASSERT_EQ(s.nodes.size(), 1000u);
    EXPECT_EQ(s.nodes[999].parent, 998);
    ASSERT_EQ(s.instances.size(), 2u);  // the static batch (empty) and the moving leaf
    EXPECT_EQ(s.instances[1].node, 999);
    const glm::mat4 leaf = nodeWorldTransforms(s, 0.5, {})[999];  // root at x = 1 (a quarter of 0..4)
    EXPECT_NEAR(leaf[3].x, 1.0f, 1e-5f);
    EXPECT_NEAR(leaf[3].y, 0.999f, 1e-4f);  // 999 nodes above the root each lift 1 mm, the root too
    // The bounds cover the whole animation: the square reaches x = 4.25.
    EXPECT_NEAR(s.bounds.max.x, 4.25f, 1e-4f);
}

TEST(SceneGraph, AMeshDrawnByTwoNodesIsStoredOnceAndDrawnTwice) {
    TempDir dir;
    QuadFile f;
    f.doc["nodes"] = {{{"mesh", 0}}, {{"mesh", 1}, {"translation", {1, 1, 0}}}, {{"mesh", 1}, {"translation", {-1, 1, 0}}}};
    f.doc["scenes"] = {{{"nodes", {0, 1, 2}}}};
    const Scene s = loadScene(f.write(dir));
    EXPECT_EQ(s.vertices.size(), 8u);  // the ground baked, the square once
    ASSERT_EQ(s.meshes.size(), 2u);
    ASSERT_EQ(s.instances.size(), 3u);
    const Scene world = worldSpaceScene(s, instanceTransforms(s, nodeWorldTransforms(s, 0.0, {})));
    EXPECT_EQ(world.triangleCount(), 6u);
    EXPECT_NEAR(world.bounds.max.y, 1.0f, 1e-6f);
    Bounds squares;
    for (size_t i = 6; i < world.vertices.size(); ++i) squares.extend(world.vertices[i].position);  // after the ground's 6
    EXPECT_VEC3_NEAR(squares.min, glm::vec3(-1.25f, 1.0f, -0.25f));
    EXPECT_VEC3_NEAR(squares.max, glm::vec3(1.25f, 1.0f, 0.25f));
}

class AnimatedShadowTest : public GpuTest {};

// Visibility IDs index the drawn (instance, triangle) list, and the resolve moves the triangle by its
// instance's transform: one mesh drawn by three nodes (moved, turned on its side, mirrored) gives
// the visibility path the classic G-buffer's normals and depth (bit-exact depth, normals within
// 1/255), and the turned instance shows its turned normal.
TEST_F(AnimatedShadowTest, InstancesResolveFromVisibilityIdsAsTheClassicGBufferDrawsThem) {
    TempDir dir;
    QuadFile f;
    const float r = 0.70710678f;  // 90 degrees about z: the square stands up, its normal along x
    f.doc["nodes"] = {{{"mesh", 0}},
                      {{"mesh", 1}, {"translation", {1, 0.5, 0}}},
                      {{"mesh", 1}, {"translation", {-1, 0.5, 0}}, {"rotation", {0, 0, r, r}}},
                      {{"mesh", 1}, {"translation", {0, 0.5, 1}}, {"scale", {-2, 1, 1}}}};
    f.doc["scenes"] = {{{"nodes", {0, 1, 2, 3}}}};
    Scene scene = loadScene(f.write(dir));
    ASSERT_EQ(scene.instances.size(), 4u);  // the static batch and the three squares
    const Camera camera = lookingAt({0.3f, 3.0f, 3.0f}, {0.0f, 0.3f, 0.0f}, 50.0f);
    const uint32_t w = 96, h = 72;
    std::map<CameraPath, std::vector<float>> normals, depths;
    for (CameraPath path : {CameraPath::Gbuffer, CameraPath::Visibility}) {
        RenderSettings s;
        s.width = w;
        s.height = h;
        s.cameraPath = path;
        s.gi = GiMode::None;
        for (Aov aov : {Aov::Normal, Aov::Depth}) {
            s.aov = aov;
            Renderer renderer(ctx(), scene, s);
            renderer.render(camera);
            (aov == Aov::Normal ? normals : depths)[path] = renderer.readHdr();
        }
    }
    int sideways = 0, normalOver = 0, depthDiffer = 0;
    for (size_t i = 0; i < size_t(w) * h; ++i) {
        const float* a = &normals[CameraPath::Gbuffer][i * 4];
        const float* b = &normals[CameraPath::Visibility][i * 4];
        sideways += std::abs(a[0]) > 0.99f;
        for (int c = 0; c < 3; ++c) normalOver += std::abs(a[c] - b[c]) > 1.0f / 255.0f;
        depthDiffer += depths[CameraPath::Gbuffer][i * 4] != depths[CameraPath::Visibility][i * 4];
    }
    EXPECT_GT(sideways, 20);  // the turned square, seen edge-on-ish from above but still covering pixels
    EXPECT_EQ(normalOver, 0);
    EXPECT_EQ(depthDiffer, 0);
}


// The sun straight down, a hard shadow map: at t = 0.25 and 0.75 the occluder is at x = -0.25 and
// 0.25, and every ground pixel seen by the camera (not behind the occluder, more than two shadow
// texels from the shadow's edge) is in shadow exactly when (x, z) is under the square there. One
// renderer over the sequence: geometry is uploaded once.
TEST_F(AnimatedShadowTest, ShadowLandsWhereTheAnimationPutsTheOccluder) {
    TempDir dir;
    Scene scene = loadScene(slidingOccluder(dir));
    scene.lights = {sunAlong({0, -1, 0})};
    const Camera camera = lookingAt({0.0f, 3.0f, 3.0f}, {0.0f, 0.0f, 0.0f}, 50.0f);
    RenderSettings s = hardShadowAov();
    s.shadow.cascades.count = 1;
    GpuScene gpu(ctx(), scene);
    Renderer renderer(ctx(), gpu, s, 1);
    const SceneMotion motion(gpu.scene(), camera, gpu.scene().lights, {}, {});
    ASSERT_TRUE(motion.moves());
    for (double t : {0.25, 0.75}) {
        const ScenePose pose = motion.at(t);
        renderer.render(FrameInputs{pose.camera, pose.lights, pose.instances});
        const std::vector<float> img = renderer.readHdr();
        const double cx = -0.5 + t;
        const HorizontalSquare shadow{cx, 0.0, 0.0, 0.25}, occluder{cx, 1.0, 0.0, 0.25};
        const double texel = 2.0 * scene.bounds.radius() / s.shadow.resolution;
        int checked = 0, wrong = 0, shadowed = 0;
        for (uint32_t y = 0; y < s.height; ++y)
            for (uint32_t x = 0; x < s.width; ++x) {
                const Ray ray = cameraRay(camera, s.width, s.height, x, y);
                const auto top = hitHorizontalPlane(ray, 1.0);
                if (top && occluder.contains(ray.origin + *top * ray.dir)) continue;
                const auto floorHit = hitHorizontalPlane(ray, 0.0);
                if (!floorHit) continue;
                const dvec3 p = ray.origin + *floorHit * ray.dir;
                if (std::abs(p.x) > 1.9 || std::abs(p.z) > 1.9 || shadow.boundaryDistance(p) < 2.0 * texel) continue;
                const bool dark = img[(size_t(y) * s.width + x) * 4] < 0.5f;
                ++checked;
                shadowed += dark;
                wrong += dark != shadow.contains(p);
            }
        EXPECT_GT(checked, 2000) << "t = " << t;
        EXPECT_GT(shadowed, 50) << "t = " << t;
        EXPECT_EQ(wrong, 0) << "t = " << t;
    }
    EXPECT_EQ(gpu.geometryUploads(), 1u);
}


// A monotonic sun sweep (azimuth 0, elevation 50 -> 80 degrees over 12 frames) over a 1 m square
// 1 m above the ground: its shadow slides along x by cot 50 - cot 80 = 0.66 m, less than its width,
// so every ground point changes state at most once (a diagonal sweep could cover and uncover a point
// near a corner). The cascade is re-fitted in a new light basis every frame: the edges along x test
// that the lattice across them stays put, the edges across x that it moves without blinking.
TEST_F(AnimatedShadowTest, SunSweepTogglesEachPixelsHardShadowAtMostOnce) {
    TempDir dir;
    QuadFile f;
    f.doc["nodes"] = {{{"mesh", 0}}, {{"mesh", 1}, {"translation", {0, 1, 0}}, {"scale", {2, 1, 2}}}};
    f.doc["scenes"] = {{{"nodes", {0, 1}}}};
    Scene scene = loadScene(f.write(dir));
    scene.lights = {sunAlong({0, -1, 0})};  // the path sets its direction
    const Camera camera = lookingAt({0.0f, 4.0f, 3.0f}, {0.0f, 0.0f, 0.0f}, 55.0f);
    RenderSettings s = hardShadowAov();
    GpuScene gpu(ctx(), scene);
    Renderer renderer(ctx(), gpu, s, 1);
    MotionPaths paths;
    paths.sun = "0,50,0,80,1";
    const SceneMotion motion(gpu.scene(), camera, gpu.scene().lights, paths, {});
    const int frames = 12;
    std::vector<int> toggles(size_t(s.width) * s.height, 0), last(toggles.size(), -1), shadowed(frames, 0);
    for (int i = 0; i < frames; ++i) {
        const ScenePose pose = motion.at(double(i) / (frames - 1));
        renderer.render(FrameInputs{pose.camera, pose.lights, pose.instances});
        const std::vector<float> img = renderer.readHdr();
        for (size_t p = 0; p < toggles.size(); ++p) {
            const int dark = img[p * 4] < 0.5f;
            shadowed[size_t(i)] += dark;
            if (last[p] >= 0 && dark != last[p]) ++toggles[p];
            last[p] = dark;
        }
    }
    EXPECT_NE(shadowed.front(), shadowed.back());  // the shadow moved
    int changed = 0, twice = 0;
    for (int t : toggles) changed += t > 0, twice += t > 1;

    std::printf("[ sun sweep ] %d pixels changed state, %d more than once\n", changed, twice);
    EXPECT_GT(changed, 100);
    EXPECT_EQ(twice, 0);
}

}  // namespace
}  // namespace penumbra::test
