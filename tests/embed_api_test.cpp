// The public API of include/penumbra as an engine uses it: its own device adopted (and refused with
// every missing feature named), scenes from memory (against the loader's, and against the analytic
// radiance of a sunlit plane), and a frame handed over as a VkImage behind a semaphore. Every test
// runs with validation and synchronization validation on.
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>

#include <gtest/gtest.h>

#include "embed_engine.h"
#include "gpu_fixture.h"
#include "penumbra/penumbra.h"
#include "scene/scene.h"

namespace penumbra::test {
namespace {

api::Settings smallSettings() {
    api::Settings s;
    s.width = 64;
    s.height = 48;
    s.shadow.filter = api::ShadowFilter::Pcf;
    s.gi = api::GiMode::Rsm;
    return s;
}

// One frame of `scene` at t on penumbra's own device (validation on), read back as RGBA8.
std::vector<uint8_t> renderOnOwnDevice(const api::SceneData& scene, const api::Settings& settings, double t = 0.0) {
    api::Device device(api::DeviceOptions{"", true, true});
    std::vector<uint8_t> texels;
    {
        api::Renderer renderer(device, scene, settings);
        renderer.render(scene.frame(t));
        texels = renderer.readRgba8();
    }
    EXPECT_EQ(device.validationMessages(), 0u) << (device.validationLog().empty() ? "" : device.validationLog()[0]);
    return texels;
}

void expectNoMessages(const Engine& engine) {
    EXPECT_EQ(engine.validationMessages(), 0u) << "validation layer reported:\n" << engine.validationLog();
}

TEST(EmbedApi, EngineDeviceRendersWhatPenumbrasOwnDeviceRenders) {
    const api::SceneData scene = api::SceneData::builtin("cornell");
    std::vector<uint8_t> engineTexels;
    Engine engine;
    {
        api::Device device(engine.external());
        api::Renderer renderer(device, scene, smallSettings());
        renderer.render(scene.frame());
        engineTexels = renderer.readRgba8();
    }
    expectNoMessages(engine);
    ASSERT_EQ(engineTexels.size(), 64u * 48u * 4u);
    EXPECT_EQ(engineTexels, renderOnOwnDevice(scene, smallSettings()));
}

TEST(EmbedApi, EngineDeviceWithoutWhatPenumbraNeedsIsRefusedNamingEachThing) {
    Engine engine;
    api::ExternalDevice everythingMissing = engine.external();
    everythingMissing.enabledFeatureChain = nullptr;
    everythingMissing.enabledExtensions.clear();
    everythingMissing.queueFamily = 99;
    try {
        api::Device device(everythingMissing);
        FAIL() << "an engine device without the required features was adopted";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        for (const char* part : {"queue family 99", "dynamicRendering (not enabled)", "geometryShader (not enabled)",
                                 "shaderBufferFloat32AtomicAdd", "VK_KHR_push_descriptor (not enabled)",
                                 "VK_EXT_shader_atomic_float (not enabled)"})
            EXPECT_NE(what.find(part), std::string::npos) << "'" << part << "' not in: " << what;
    }
    // One feature left off: that one is named, and nothing else.
    api::RequiredFeatures almost;
    almost.v12.shaderOutputLayer = VK_FALSE;
    api::ExternalDevice oneMissing = engine.external();
    oneMissing.enabledFeatureChain = &almost.features2;
    try {
        api::Device device(oneMissing);
        FAIL() << "an engine device without shaderOutputLayer was adopted";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), "the engine's device '" + std::string(api::Device().name()) +
                                             "' cannot run penumbra; it needs: shaderOutputLayer (not enabled)");
    }
    expectNoMessages(engine);
}

TEST(EmbedApi, FrameImageHoldsTheFrameAndWaitsForTheEngine) {
    const api::SceneData scene = api::SceneData::builtin("cornell");
    Engine engine;
    {
        api::Device device(engine.external());
        api::Renderer renderer(device, scene, smallSettings());
        const VkSemaphore engineDone = engine.newSemaphore();
        const api::FrameImage first = renderer.submitToImage(scene.frame(0.0));
        EXPECT_EQ(first.format, VK_FORMAT_R8G8B8A8_UNORM);
        EXPECT_EQ(first.layout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        EXPECT_EQ(first.width, 64u);
        EXPECT_EQ(first.height, 48u);
        ASSERT_NE(first.view, VK_NULL_HANDLE);
        const std::vector<uint8_t> firstTexels = engine.copyOut(first, engineDone);
        renderer.finish();
        EXPECT_EQ(firstTexels, renderer.readRgba8());
        // The built-in cornell's light sweeps: a second frame differs, and waits for the engine's copy.
        const api::FrameImage second = renderer.submitToImage(scene.frame(1.5), engineDone);
        EXPECT_EQ(second.image, first.image);
        const std::vector<uint8_t> secondTexels = engine.copyOut(second, VK_NULL_HANDLE);
        renderer.finish();
        EXPECT_EQ(secondTexels, renderer.readRgba8());
        EXPECT_NE(secondTexels, firstTexels);
        EXPECT_EQ(secondTexels, renderOnOwnDevice(scene, smallSettings(), 1.5));
        // Another size: a new image of that size, the frame in it.
        api::Settings smaller = smallSettings();
        smaller.width = 40;
        renderer.apply(smaller);
        const api::FrameImage third = renderer.submitToImage(scene.frame(1.5));
        EXPECT_EQ(third.width, 40u);
        const std::vector<uint8_t> thirdTexels = engine.copyOut(third, VK_NULL_HANDLE);
        renderer.finish();
        EXPECT_EQ(thirdTexels, renderer.readRgba8());
        EXPECT_EQ(thirdTexels.size(), 40u * 48u * 4u);
    }
    expectNoMessages(engine);
}

// The built-in cornell box handed in as arrays, as an engine would.
api::SceneDesc cornellArrays() {
    Scene s = makeBuiltinScene("cornell");
    addDefaultsIfMissing(s);
    api::SceneDesc d;
    d.name = "cornell from memory";
    for (const Vertex& v : s.vertices)
        d.vertices.push_back({{v.position.x, v.position.y, v.position.z}, {v.normal.x, v.normal.y, v.normal.z},
                              {v.uv.x, v.uv.y}});
    d.indices = s.indices;
    for (const Draw& draw : s.draws) d.draws.push_back({draw.firstIndex, draw.indexCount, draw.material});
    for (const Material& m : s.materials) {
        api::Material& out = d.materials.emplace_back();
        std::memcpy(out.baseColor, &m.baseColor, sizeof(out.baseColor));
        EXPECT_EQ(m.baseColorTexture, -1);
    }
    for (const Light& l : s.lights) {
        api::Light& out = d.lights.emplace_back();
        out.type = api::LightType(l.type);
        out.position = {l.position.x, l.position.y, l.position.z};
        out.direction = {l.direction.x, l.direction.y, l.direction.z};
        out.color = {l.color.x, l.color.y, l.color.z};
        out.intensity = l.intensity, out.range = l.range;
        out.innerConeAngle = l.innerConeAngle, out.outerConeAngle = l.outerConeAngle;
    }
    api::Camera& c = d.cameras.emplace_back();
    const Camera& sc = s.cameras[0];
    c.eye = {sc.eye.x, sc.eye.y, sc.eye.z}, c.target = {sc.target.x, sc.target.y, sc.target.z};
    c.up = {sc.up.x, sc.up.y, sc.up.z}, c.fovy = sc.fovy, c.znear = sc.znear, c.zfar = sc.zfar;
    EXPECT_TRUE(s.strands.empty());
    EXPECT_EQ(s.instances.size(), 1u);
    return d;
}

TEST(EmbedApi, SceneFromMemoryRendersAsTheLoadedScene) {
    const api::SceneData memory = api::SceneData::fromMemory(cornellArrays());
    EXPECT_TRUE(memory.warnings().empty());
    EXPECT_EQ(memory.triangleCount(), api::SceneData::builtin("cornell").triangleCount());
    EXPECT_EQ(renderOnOwnDevice(memory, smallSettings()),
              renderOnOwnDevice(api::SceneData::builtin("cornell"), smallSettings()));
}

// A 10 m square floor under a sun straight above: every pixel sees albedo * E / pi.
api::SceneDesc sunlitFloor(float albedo, float irradiance) {
    api::SceneDesc d;
    for (float x : {-5.0f, 5.0f})
        for (float z : {-5.0f, 5.0f}) d.vertices.push_back({{x, 0.0f, z}, {0.0f, 2.0f, 0.0f}, {0.0f, 0.0f}});
    d.indices = {0, 1, 2, 2, 1, 3};
    api::Material& m = d.materials.emplace_back();
    m.baseColor[0] = m.baseColor[1] = m.baseColor[2] = albedo;
    api::Light& sun = d.lights.emplace_back();
    sun.type = api::LightType::Directional;
    sun.direction = {0.0f, -1.0f, 0.0f};
    sun.intensity = irradiance;
    api::Camera& c = d.cameras.emplace_back();
    c.eye = {0.0f, 3.0f, 0.0f}, c.target = {0.0f, 0.0f, 0.0f}, c.up = {0.0f, 0.0f, -1.0f};
    c.fovy = 1.0f;
    return d;
}

TEST(EmbedApi, SceneFromMemoryUnderASunGivesTheAnalyticRadiance) {
    // An albedo the sRGB8 G-buffer stores exactly (code 188): any other is its nearest code.
    const double albedo = srgbToLinear(188.0 / 255.0);
    const api::SceneData floor = api::SceneData::fromMemory(sunlitFloor(float(albedo), 2.0f));
    ASSERT_EQ(floor.warnings().size(), 1u);  // the normals given at length 2
    EXPECT_NE(floor.warnings()[0].find("4 normals and directions scaled"), std::string::npos) << floor.warnings()[0];
    api::Settings settings;
    settings.width = settings.height = 16;
    api::Device device(api::DeviceOptions{"", true, true});
    {
        api::Renderer renderer(device, floor, settings);
        renderer.render(floor.frame());
        const std::vector<float> hdr = renderer.readRgba32f();
        const double expected = albedo * 2.0 / M_PI;
        // lavapipe's sRGB decode is approximate to ~1e-3: a quarter of the albedo's code step.
        const double tolerance = 0.25 * (albedo - srgbToLinear(187.0 / 255.0)) * 2.0 / M_PI;
        for (uint32_t pixel : {0u, 8u * 16u + 8u, 16u * 16u - 1u})
            for (int channel = 0; channel < 3; ++channel)
                EXPECT_NEAR(hdr[pixel * 4 + channel], expected, tolerance) << "pixel " << pixel;
    }
    EXPECT_EQ(device.validationMessages(), 0u);
}

TEST(EmbedApi, SceneFromMemoryRefusesBadArraysWithOneLine) {
    auto refused = [](const api::SceneDesc& d, const std::string& part) {
        try {
            api::SceneData::fromMemory(d);
            ADD_FAILURE() << "accepted a scene that should fail with '" << part << "'";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
        }
    };
    api::SceneDesc d = sunlitFloor(0.5f, 1.0f);
    d.indices[4] = 4;
    refused(d, "index 4 is 4, past the 4 vertices");
    d = sunlitFloor(0.5f, 1.0f);
    d.draws = {{3, 6, 0}};
    refused(d, "draw 0 reaches past the 6 indices");
    d.draws = {{0, 6, 1}};
    refused(d, "draw 0 names material 1 of 1");
    d.draws = {{0, 4, 0}};
    refused(d, "draw 0 has 4 indices, not whole triangles");
    d = sunlitFloor(0.5f, 1.0f);
    d.vertices[1].normal = {};
    refused(d, "vertex 1's normal is zero or not finite");
    d = sunlitFloor(0.5f, 1.0f);
    d.vertices[2].position.y = NAN;
    refused(d, "vertex 2's position is not finite");
    refused(api::SceneDesc{}, "no vertices or no indices");
}

TEST(EmbedApi, SettingsOutOfRangeAreRefusedBeforeAnyWork) {
    api::Device device;
    const api::SceneData scene = api::SceneData::builtin("plane");
    api::Settings settings;
    settings.width = 0;
    EXPECT_THROW((api::Renderer{device, scene, settings}), std::invalid_argument);
    settings = api::Settings();
    settings.shadow.resolution = 8;
    EXPECT_THROW((api::Renderer{device, scene, settings}), std::invalid_argument);
}

}  // namespace
}  // namespace penumbra::test
