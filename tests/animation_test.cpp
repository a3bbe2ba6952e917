// Motion (issue 12): glTF animation sampling against hand-computed values, the node hierarchy kept
// through loading (1000 deep, walked without recursion), instancing (a mesh drawn by two nodes is
// stored once), an animated occluder whose hard shadow lands where the animation puts it at two
// times, and a sequence that uploads geometry once.
#include <map>

#include <array>
#include <cstring>
#include <glm/gtc/constants.hpp>

#include "gltf_test_util.h"
#include "gpu_fixture.h"
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

// Two quads in one buffer: mesh 0 the ground (4 m square at y = 0), mesh 1 a 0.5 m square at y = 0
// (its node lifts it); both facing +y, double-sided.
struct QuadFile {
    std::vector<uint8_t> bin;
    json doc;
    QuadFile() {
        auto quad = [&](float h) {
            for (float z : {-h, h})
                for (float x : {-h, h}) append(bin, x), append(bin, 0.0f), append(bin, z);
        };
        quad(2.0f);
        quad(0.25f);
        for (int q = 0; q < 2; ++q)
            for (uint16_t i : {0, 2, 1, 1, 2, 3}) append(bin, uint16_t(i));
        doc = json{{"asset", {{"version", "2.0"}}},
                   {"scene", 0},
                   {"buffers", json::array()},
                   {"bufferViews", {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 96}},
                                    {{"buffer", 0}, {"byteOffset", 96}, {"byteLength", 24}}}},
                   {"accessors",
                    {{{"bufferView", 0}, {"byteOffset", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"},
                      {"min", {-2, 0, -2}}, {"max", {2, 0, 2}}},
                     {{"bufferView", 0}, {"byteOffset", 48}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"},
                      {"min", {-0.25, 0, -0.25}}, {"max", {0.25, 0, 0.25}}},
                     {{"bufferView", 1}, {"byteOffset", 0}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}},
                     {{"bufferView", 1}, {"byteOffset", 12}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}},
                   {"materials", {{{"doubleSided", true}}}}};
        for (int m = 0; m < 2; ++m) {
            json primitive{{"attributes", {{"POSITION", m}}}, {"indices", 2 + m}, {"material", 0}};
            doc["meshes"].push_back({{"primitives", json::array({primitive})}});
        }
    }
    // Adds a float accessor (after the geometry) and returns its index.
    int addFloats(const std::vector<float>& v, const char* type, int count) {
        const size_t offset = bin.size();
        for (float f : v) append(bin, f);
        doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", v.size() * 4}});
        json acc{{"bufferView", doc["bufferViews"].size() - 1}, {"componentType", 5126}, {"count", count}, {"type", type}};
        if (std::string(type) == "SCALAR") acc["min"] = {v.front()}, acc["max"] = {v.back()};
        doc["accessors"].push_back(acc);
        return int(doc["accessors"].size() - 1);
    }
    std::string write(const TempDir& dir) {
        doc["buffers"] = {{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}};
        const std::string path = dir.file("scene.gltf");
        writeFile(path, doc.dump());
        return path;
    }
};

// The ground, and the small square at y = 1 sliding along x from -0.5 (t = 0) to 0.5 (t = 1).
std::string slidingOccluder(const TempDir& dir) {
    QuadFile f;
    const int times = f.addFloats({0.0f, 1.0f}, "SCALAR", 2);
    const int values = f.addFloats({-0.5f, 1.0f, 0.0f, 0.5f, 1.0f, 0.0f}, "VEC3", 2);
    f.doc["nodes"] = {{{"mesh", 0}}, {{"mesh", 1}, {"translation", {-0.5, 1, 0}}}};
    f.doc["scenes"] = {{{"nodes", {0, 1}}}};
    f.doc["animations"] = {{{"channels", {{{"sampler", 0}, {"target", {{"node", 1}, {"path", "translation"}}}}}},
                            {"samplers", {{{"input", times}, {"output", values}, {"interpolation", "LINEAR"}}}}}};
    return f.write(dir);
}

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

// A camera at `eye` looking at `target` (y up).
Camera lookingAt(glm::vec3 eye, glm::vec3 target, float fovyDegrees) {
    Camera c;
    c.eye = eye;
    c.target = target;
    c.fovy = glm::radians(fovyDegrees);
    return c;
}

// 96x72 hard-shadow AOV frames with one 512^2 map, no GI: where a pixel is lit is all the tests read.
RenderSettings hardShadowAov() {
    RenderSettings s;
    s.width = 96;
    s.height = 72;
    s.aov = Aov::Shadow;
    s.gi = GiMode::None;
    s.shadow.filter = ShadowFilter::Hard;
    s.shadow.resolution = 512;
    return s;
}

Light sunAlong(glm::vec3 direction) {
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = direction;
    sun.intensity = 3.0f;
    return sun;
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
                const auto ground = hitHorizontalPlane(ray, 0.0);
                if (!ground) continue;
                const dvec3 p = ray.origin + *ground * ray.dir;
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

// Camera-only motion leaves LPV's light where it was: cascades snap to whole cells, and the spot
// light's RSM does not depend on the camera. Cornell with three cascades nested around the eye, the
// eye moved by fractions of a cell: the summed light volume at the same world cell is unchanged
// (within 4 ulps: float-atomic injection sums in a varying order) at cells 2 or more cells inside
// both grids, and 5 (the propagation steps + 1: light from beyond a border never enters a grid).
// Measured: no cell differs, with camera geometry off and on (printed).
TEST_F(AnimatedShadowTest, CameraOnlyMotionLeavesLpvLightAtFixedWorldCells) {
    const Scene scene = makeBuiltinScene("cornell");
    RenderSettings s;
    s.width = 64;
    s.height = 48;
    s.gi = GiMode::Lpv;
    s.lpv.cascades = 3;
    s.lpv.resolution = 16;
    s.lpv.iterations = 4;
    s.lpv.rsmResolution = 256;
    s.lpv.vplResolution = 64;
    for (bool cameraGeometry : {false, true}) {
        s.lpv.cameraGeometry = cameraGeometry;
        Renderer renderer(ctx(), scene, s);
        struct Frame {
            std::vector<glm::vec4> accum;
            std::array<gpu::GpuLpvCascade, LPV_MAX_CASCADES> cascades;
        };
        std::vector<Frame> frames;
        for (const glm::vec3 move : {glm::vec3(0.0f), glm::vec3(0.037f, 0.011f, -0.053f) * scene.bounds.radius()}) {
            Camera c = scene.cameras[0];
            c.eye += move;
            c.target += move;
            renderer.render(c);
            const vk::Buffer& accum = renderer.lpv()->accumulated();
            const std::vector<uint8_t> bytes = renderer.commands().readBuffer(accum, accum.size());
            Frame f;
            f.accum.resize(bytes.size() / sizeof(glm::vec4));
            std::memcpy(f.accum.data(), bytes.data(), bytes.size());
            std::copy_n(renderer.lpv()->constants().cascades, LPV_MAX_CASCADES, f.cascades.begin());
            frames.push_back(std::move(f));
        }
        const int res = int(s.lpv.resolution), inner = int(s.lpv.iterations) + 1;
        const size_t cells = size_t(res) * res * res;
        for (int margin : {inner, 2}) {
            size_t compared = 0, differ = 0, shifted = 0;
            double worst = 0.0;
            for (uint32_t k = 0; k < s.lpv.cascades; ++k) {
                const glm::vec4 a = frames[0].cascades[k].origin, b = frames[1].cascades[k].origin;
                ASSERT_EQ(a.w, b.w);
                const glm::ivec3 shift = glm::ivec3(glm::round((glm::vec3(b) - glm::vec3(a)) / a.w));
                ASSERT_LT(glm::length(glm::vec3(b) - glm::vec3(a) - glm::vec3(shift) * a.w), 1e-3f * a.w);
                shifted += shift != glm::ivec3(0);
                for (int z = margin; z < res - margin; ++z)
                    for (int y = margin; y < res - margin; ++y)
                        for (int x = margin; x < res - margin; ++x) {
                            const glm::ivec3 ca = glm::ivec3(x, y, z) + shift;  // the same world cell in frame 0
                            if (glm::any(glm::lessThan(ca, glm::ivec3(margin))) ||
                                glm::any(glm::greaterThanEqual(ca, glm::ivec3(res - margin))))
                                continue;
                            for (uint32_t ch = 0; ch < 3; ++ch) {
                                const size_t base = (size_t(k) * 3 + ch) * cells;
                                const glm::vec4 va = frames[0].accum[base + (size_t(ca.z) * res + ca.y) * res + ca.x];
                                const glm::vec4 vb = frames[1].accum[base + (size_t(z) * res + y) * res + x];
                                ++compared;
                                const float scale = std::max(glm::length(va), 1e-30f);
                                const double d = glm::length(va - vb) / scale;
                                worst = std::max(worst, d);
                                differ += d > 4.0 * 1.2e-7;
                            }
                        }
            }
            std::printf("[ lpv camera-only ] camera geometry %s, %d cells inside the borders: %zu of %zu cell "
                        "colours differ (largest relative change %.2e); %zu cascades moved\n",
                        cameraGeometry ? "on" : "off", margin, differ, compared, worst, shifted);
            EXPECT_GT(shifted, 0u);
            EXPECT_GT(compared, 100u);
            if (!cameraGeometry) EXPECT_EQ(differ, 0u);
        }
    }
}


// Where a pinhole camera shows world point q, in continuous pixel coordinates (the inverse of
// cameraRay: pixel (x, y)'s centre is (x + 0.5, y + 0.5)).
glm::dvec2 pixelOf(const Camera& camera, uint32_t width, uint32_t height, const dvec3& q) {
    const dvec3 eye(camera.eye), f = glm::normalize(dvec3(camera.target) - eye);
    const dvec3 r = glm::normalize(glm::cross(f, dvec3(camera.up))), u = glm::cross(r, f);
    const dvec3 d = q - eye;
    const double t = std::tan(0.5 * double(camera.fovy)), aspect = double(width) / double(height);
    const double sx = glm::dot(d, r) / glm::dot(d, f) / (t * aspect), sy = glm::dot(d, u) / glm::dot(d, f) / t;
    return {(sx + 1.0) * 0.5 * width, (1.0 - sy) * 0.5 * height};
}

// The velocity AOV against that projection: every surface pixel's velocity is its centre minus where
// its world point was in the previous frame. Two motions: the square sliding along x at 1 m/s under a
// still camera (t = 0.5, the previous frame 1/30 s earlier: the visibility path follows the moving
// instance through its ID), and the still scene under a camera that moved (both camera paths).
TEST_F(AnimatedShadowTest, VelocityIsWhereEachPointWasInThePreviousFrame) {
    TempDir dir;
    const Scene scene = loadScene(slidingOccluder(dir));
    const Camera camera = lookingAt({0.0f, 3.0f, 3.0f}, {0.0f, 0.0f, 0.0f}, 50.0f);
    Camera moved = camera;
    moved.eye += glm::vec3(0.06f, 0.02f, -0.04f);
    moved.target += glm::vec3(0.03f, 0.0f, 0.01f);
    const double t = 0.5, dt = 1.0 / 30.0;
    for (CameraPath path : {CameraPath::Visibility, CameraPath::Gbuffer}) {
        RenderSettings s;
        s.width = 96;
        s.height = 72;
        s.aov = Aov::Velocity;
        s.gi = GiMode::None;
        s.cameraPath = path;
        GpuScene gpu(ctx(), scene);
        Renderer renderer(ctx(), gpu, s, 1);
        const SceneMotion motion(gpu.scene(), camera, gpu.scene().lights, {}, {});
        for (bool objectMoves : {true, false}) {
            if (objectMoves && path == CameraPath::Gbuffer) continue;  // camera motion only (README)
            SCOPED_TRACE(objectMoves ? "the square moves" : "the camera moves");
            const ScenePose now = motion.at(t);
            FrameInputs in{camera, now.lights, now.instances};
            const Camera& before = objectMoves ? camera : moved;
            in.previous = FrameInputs::Previous{before, motion.at(objectMoves ? t - dt : t).instances};
            renderer.render(in);
            const std::vector<float> img = renderer.readHdr();
            const HorizontalSquare square{-0.5 + t, 1.0, 0.0, 0.25};
            int checked = 0, onSquare = 0;
            double worst = 0.0;
            for (uint32_t y = 0; y < s.height; ++y)
                for (uint32_t x = 0; x < s.width; ++x) {
                    const Ray ray = cameraRay(camera, s.width, s.height, x, y);
                    dvec3 q, then;
                    const auto top = hitHorizontalPlane(ray, 1.0);
                    if (top && square.contains(ray.origin + *top * ray.dir)) {
                        q = ray.origin + *top * ray.dir;
                        if (square.boundaryDistance(q) < 0.03) continue;
                        then = objectMoves ? q - dvec3(dt, 0.0, 0.0) : q;
                        ++onSquare;
                    } else {
                        const auto ground = hitHorizontalPlane(ray, 0.0);
                        if (!ground) continue;
                        q = ray.origin + *ground * ray.dir;
                        if (std::abs(q.x) > 1.9 || std::abs(q.z) > 1.9) continue;
                        if (top && square.boundaryDistance(ray.origin + *top * ray.dir) < 0.03) continue;
                        then = q;
                    }
                    const glm::dvec2 expected = glm::dvec2(x + 0.5, y + 0.5) - pixelOf(before, s.width, s.height, then);
                    const float* v = &img[(size_t(y) * s.width + x) * 4];
                    worst = std::max(worst, glm::length(glm::dvec2(v[0], v[1]) - expected));
                    ++checked;
                }
            std::printf("[ velocity ] %s path, %s: %d pixels (%d on the square), largest error %.4f px\n",
                        path == CameraPath::Visibility ? "visibility" : "gbuffer",
                        objectMoves ? "square moving" : "camera moving", checked, onSquare, worst);
            EXPECT_GT(checked, 3000);
            EXPECT_GT(onSquare, 30);  // the 0.5 m square covers about 50 pixels
            EXPECT_LT(worst, 0.01);
        }
    }
}


// RSM under a moving light: with bilinear VPLs (--rsm-vpls bilinear) a gather sample's light is
// continuous in the light's position; with nearest VPLs it jumps whenever the RSM's texel lattice
// moves a texel edge across the sample. A spot light above a floor (the only surface in its map, so
// that no geometric edge makes the RSM itself jump) lights a wall outside its cone by the bounce.
// Moving the light by h and by h / 2, the RMS of the change of the wall's indirect light scales like
// the step for a continuous function (x2 from h / 2 to h), while jumps, whose count grows with the
// step but not their size, scale like its square root (x1.41). Steps of 1/16 and 1/32 RSM texel.
TEST_F(AnimatedShadowTest, BilinearVplsMoveContinuouslyWithTheLight) {
    TempDir dir;
    QuadFile f;
    const float r = 0.70710678f;
    f.doc["nodes"] = {{{"mesh", 0}}, {{"mesh", 1}, {"translation", {1.5, 1, 0}}, {"rotation", {0, 0, r, r}},
                                      {"scale", {4, 1, 4}}}};
    f.doc["scenes"] = {{{"nodes", {0, 1}}}};
    Scene scene = loadScene(f.write(dir));
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0.0f, 1.0f, 0.0f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.outerConeAngle = glm::radians(30.0f);
    spot.innerConeAngle = glm::radians(20.0f);
    spot.intensity = 10.0f;
    scene.lights = {spot};
    const Camera camera = lookingAt({-1.0f, 1.2f, 0.3f}, {1.5f, 0.8f, 0.0f}, 50.0f);
    RenderSettings s;
    s.width = 64;
    s.height = 48;
    s.gi = GiMode::Rsm;
    s.rsm.mode = RsmMode::Full;  // no interpolation: its own decisions would jump too
    s.rsm.resolution = 128;
    s.rsm.samples = 256;
    s.aov = Aov::Indirect;
    const float h = 0.0625f * 2.0f * std::tan(spot.outerConeAngle) / float(s.rsm.resolution);  // 1/16 texel on the floor
    double ratio[2] = {0.0, 0.0};
    for (int bilinear = 0; bilinear < 2; ++bilinear) {
        s.rsm.bilinearVpls = bilinear == 1;
        Renderer renderer(ctx(), scene, s);
        auto render = [&](float dx) {
            std::vector<Light> lights = scene.lights;
            lights[0].position.x += dx;
            renderer.render(FrameInputs{camera, lights});
            return renderer.readHdr();
        };
        const std::vector<float> base = render(0.0f);
        double rms[2];
        for (int k = 0; k < 2; ++k) {
            const std::vector<float> moved = render(k == 0 ? h : 0.5f * h);
            double sum = 0.0;
            size_t n = 0;
            for (size_t i = 0; i < base.size(); i += 4) {
                if (base[i] + base[i + 1] + base[i + 2] <= 0.0f) continue;  // the floor: no bounce from its own plane
                for (int c = 0; c < 3; ++c) sum += std::pow(double(moved[i + c]) - double(base[i + c]), 2.0);
                ++n;
            }
            ASSERT_GT(n, 300u) << "wall pixels lit by the bounce";
            rms[k] = std::sqrt(sum / double(n));
        }
        ASSERT_GT(rms[1], 0.0);
        ratio[bilinear] = rms[0] / rms[1];
        std::printf("[ rsm motion ] %s VPLs: RMS change %.3e at h, %.3e at h/2: ratio %.2f\n",
                    bilinear ? "bilinear" : "nearest", rms[0], rms[1], ratio[bilinear]);
    }
    // Bilinear: continuous, 2 up to second-order terms. Nearest: the light's continuous change (the
    // floor's irradiance moves) plus jumps, which pull the ratio towards 1.41. Measured: 2.00 and 1.67.
    EXPECT_NEAR(ratio[1], 2.0, 0.1);
    EXPECT_LT(ratio[0], 1.8);
}


// --gi-temporal is an exponential average of the frames, reprojected: under a still camera whose light
// changes from A to B after the first frame, frame k's indirect light is E_B + (1 - alpha)^k (E_A - E_B)
// at every pixel (the history reprojects onto itself). That is its step response, the lag the README
// reports: after k frames the old light still weighs (1 - alpha)^k. The first frame has no history.
TEST_F(AnimatedShadowTest, TemporalGiIsAnExponentialAverageOfTheFrames) {
    const Scene scene = makeBuiltinScene("cornell");
    RenderSettings s;
    s.width = 64;
    s.height = 48;
    s.gi = GiMode::Rsm;
    s.rsm.mode = RsmMode::Full;
    s.rsm.resolution = 128;
    s.rsm.samples = 64;
    s.aov = Aov::Indirect;
    const Camera& camera = scene.cameras[0];
    std::vector<Light> lightB = scene.lights;
    lightB[0].position.x += 0.3f;
    lightB[0].intensity *= 1.5f;
    auto still = [&](const std::vector<Light>& lights) {
        Renderer r(ctx(), scene, s);
        r.render(FrameInputs{camera, lights});
        return r.readHdr();
    };
    const std::vector<float> a = still(scene.lights), b = still(lightB);
    s.giTemporal = true;
    s.giTemporalAlpha = 0.25f;
    Renderer r(ctx(), scene, s);
    r.render(FrameInputs{camera, scene.lights});
    EXPECT_EQ(r.readHdr(), a) << "the first frame has no history";
    double largest = 0.0;
    for (const float d : a) largest = std::max(largest, double(std::abs(d)));
    for (int k = 1; k <= 3; ++k) {
        r.render(FrameInputs{camera, lightB});
        const std::vector<float> img = r.readHdr();
        const double keep = std::pow(0.75, k);
        double worst = 0.0;
        for (size_t i = 0; i < img.size(); i += 4)
            for (int c = 0; c < 3; ++c) {
                const double expected = b[i + c] + keep * (double(a[i + c]) - b[i + c]);
                worst = std::max(worst, std::abs(img[i + c] - expected));
            }
        EXPECT_LT(worst, 1e-5 * largest) << "frame " << k;
    }
}

}  // namespace
}  // namespace penumbra::test
