// Motion (issue 12): glTF animation sampling against hand-computed values, the node hierarchy kept
// through loading (1000 deep, walked without recursion), instancing (a mesh drawn by two nodes is
// stored once), an animated occluder whose hard shadow lands where the animation puts it at two
// times, and a sequence that uploads geometry once.
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

class AnimatedShadowTest : public GpuTest {};

// The sun straight down, a hard shadow map: at t = 0.25 and 0.75 the occluder is at x = -0.25 and
// 0.25, and every ground pixel seen by the camera (not behind the occluder, more than two shadow
// texels from the shadow's edge) is in shadow exactly when (x, z) is under the square there. One
// renderer over the sequence: geometry is uploaded once.
TEST_F(AnimatedShadowTest, ShadowLandsWhereTheAnimationPutsTheOccluder) {
    TempDir dir;
    Scene scene = loadScene(slidingOccluder(dir));
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {0, -1, 0};
    sun.intensity = 3.0f;
    scene.lights = {sun};
    Camera camera;
    camera.eye = {0.0f, 3.0f, 3.0f};
    camera.target = {0.0f, 0.0f, 0.0f};
    camera.fovy = glm::radians(50.0f);
    RenderSettings s;
    s.width = 96;
    s.height = 72;
    s.aov = Aov::Shadow;
    s.gi = GiMode::None;
    s.shadow.filter = ShadowFilter::Hard;
    s.shadow.resolution = 512;
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

}  // namespace
}  // namespace penumbra::test
