// The sky's light with occlusion (src/sky_light) against analytic answers: a uniform sky of radiance
// L over the upper hemisphere gives an open upward plane pi L, and nothing inside a closed room; and
// on the street against the sky's occlusion traced by Embree.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "enclosed_plane.h"
#include "gpu_fixture.h"
#include "readback.h"
#include "reference/ray_scene.h"
#include "scene/motion.h"
#include "sky_light/sky_light_technique.h"
#include "test_renderer.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

// The uniform sky of radiance L over the upper hemisphere, black below (`--sky uniform,L,L,L`).
SkySettings uniformSky(float radiance) {
    SkySettings sky;
    sky.kind = SkyKind::Uniform;
    sky.uniformRadiance = glm::vec3(radiance);
    return sky;
}

class SkyLightTest : public GpuTest {
protected:
    void readSurfaces(TestRenderer& r) {
        const auto world = gbufferWorldPositions(r);
        const std::vector<uint8_t> normal = r.commands().readImage(r.gbuffer().normal, 8);
        position_.assign(world.size(), glm::dvec3(0.0));
        normal_.assign(world.size(), glm::dvec3(0.0));
        for (size_t i = 0; i < world.size(); ++i) {
            if (!world[i]) continue;
            position_[i] = *world[i];
            glm::dvec3 n = glm::normalize(glm::dvec3(half(normal, i * 4), half(normal, i * 4 + 1), half(normal, i * 4 + 2)));
            if (glm::dot(n, glm::dvec3(r.frameUniforms().eye) - position_[i]) < 0.0) n = -n;
            normal_[i] = n;
        }
    }

    // The sky's irradiance per pixel (RGBA32F) of a frame of `scene` from its first camera, its
    // lights off.
    std::vector<float> skyIrradiance(Scene scene, const SkySettings& sky, RenderSettings s = {}) {
        for (Light& l : scene.lights) l.intensity = 0.0f;
        s.lighting.sky = sky;
        s.width = 64, s.height = 48, s.giTemporal = false;
        TestRenderer r(ctx(), scene, s);
        r.render(scene.cameras.at(0));
        SkyLightTechnique* t = r.find<SkyLightTechnique>();
        EXPECT_NE(t, nullptr);
        if (!t) return {};
        const std::vector<uint8_t> bytes = r.commands().readImage(t->irradiance(), 16);
        std::vector<float> out(bytes.size() / 4);
        for (size_t i = 0; i < out.size(); ++i) out[i] = f32(bytes, i);
        direct_ = r.readHdr();
        readSurfaces(r);
        return out;
    }
    // Cornell's sliding box under a uniform sky, the view still: after the box moves, each of
    // `frames` frames runs `pass` once, the next none, and the result then equals that of a renderer
    // that saw the box there first.
    void slidingBoxCatchesUp(SkyVisibility visibility, const std::string& pass, int frames);
    std::vector<float> direct_;  // the last frame's output AOV (direct unless the settings say)
    // The last frame's surfaces: world position and the normal the camera sees (zero: none).
    std::vector<glm::dvec3> position_, normal_;
};

// A uniform sky of radiance 1 seen from `x` over its hemisphere about n: pi times the cosine-weighted
// share of rays that leave the scene upward, by `count` stratified rays traced through Embree.
double tracedSkyIrradiance(const reference::RayScene& rays, const glm::dvec3& x, const glm::dvec3& n, float eps,
                           int side) {
    const glm::dvec3 t = glm::normalize(std::abs(n.y) < 0.9 ? glm::cross(n, glm::dvec3(0, 1, 0))
                                                           : glm::cross(n, glm::dvec3(1, 0, 0)));
    const glm::dvec3 b = glm::cross(n, t);
    int open = 0;
    for (int i = 0; i < side; ++i)
        for (int j = 0; j < side; ++j) {
            const double u = (i + 0.5) / side, phi = 2.0 * M_PI * (j + 0.5) / side, r = std::sqrt(u);
            const glm::dvec3 d = t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + n * std::sqrt(1.0 - u);
            if (d.y <= 0.0) continue;  // black below the horizon
            if (!rays.intersect(glm::vec3(x + 10.0 * double(eps) * n), glm::vec3(d), eps, 1e30f, {0, -1, true})) ++open;
        }
    return M_PI * open / double(side * side);
}

// The sky light's irradiance image (RGBA32F) of the renderer's last frame.
std::vector<float> irradiance(TestRenderer& r) {
    const std::vector<uint8_t> bytes = r.commands().readImage(r.find<SkyLightTechnique>()->irradiance(), 16);
    std::vector<float> out(bytes.size() / 4);
    for (size_t i = 0; i < out.size(); ++i) out[i] = f32(bytes, i);
    return out;
}

// sum |a - b| / sum |b| over every channel.
double relativeL1(const std::vector<float>& a, const std::vector<float>& b) {
    double differs = 0.0, sum = 1e-30;
    for (size_t i = 0; i < a.size(); ++i) differs += std::abs(a[i] - b[i]), sum += std::abs(b[i]);
    return differs / sum;
}

void SkyLightTest::slidingBoxCatchesUp(SkyVisibility visibility, const std::string& pass, int frames) {
    const Scene scene = makeBuiltinScene("cornell-moving");
    RenderSettings s;
    s.lighting.sky = uniformSky(1.0f);
    s.skyLight.visibility = visibility;
    s.width = 64, s.height = 48, s.giTemporal = false;
    const SceneMotion motion(scene, scene.cameras.at(0), scene.lights, {}, {});
    auto frame = [&](double t) {
        const ScenePose pose = motion.at(t);
        return FrameInputs{pose.camera, pose.lights, pose.instances, {}, {}};
    };
    auto runs = [&pass](const TestRenderer& r) {
        return std::count_if(r.passes().begin(), r.passes().end(), [&pass](const PassDesc& p) { return p.name == pass; });
    };
    TestRenderer moving(ctx(), scene, s);
    moving.render(frame(0.0));
    const std::vector<float> before = irradiance(moving);
    for (int k = 0; k < frames; ++k) {
        moving.render(frame(0.75));
        EXPECT_EQ(runs(moving), 1) << "frame " << k;
    }
    const std::vector<float> after = irradiance(moving);
    moving.render(frame(0.75));
    EXPECT_EQ(runs(moving), 0);
    TestRenderer fresh(ctx(), scene, s);
    fresh.render(frame(0.75));
    const std::vector<float> expected = irradiance(fresh);
    ASSERT_EQ(after.size(), expected.size());
    EXPECT_GT(relativeL1(after, before), 1e-3) << "the box changes the sky's light";
    EXPECT_LE(relativeL1(after, expected), 1e-6);
}

}  // namespace

TEST_F(SkyLightTest, UniformSkyGivesAnOpenPlanePiL) {
    constexpr float kL = 0.8f;
    RenderSettings s;
    s.aov = Aov::Direct;
    const std::vector<float> e = skyIrradiance(makeBuiltinScene("plane"), uniformSky(kL), s);
    ASSERT_EQ(e.size(), 64u * 48u * 4u);
    size_t checked = 0;
    for (size_t i = 0; i < e.size(); i += 4) {
        if (e[i + 3] < 0.5f) continue;  // the background
        ++checked;
        for (int c = 0; c < 3; ++c) {
            // The sky's SH come from a table of its radiance (core/sky.h): exact to about 1e-4.
            EXPECT_NEAR(e[i + c], float(M_PI) * kL, 1e-3f) << "pixel " << i / 4;
            // The lighting adds albedo / pi times it to the direct light (the plane's albedo 0.5).
            EXPECT_NEAR(direct_[i + c], 0.5f / float(M_PI) * e[i + c], 1e-5f) << "pixel " << i / 4;
        }
    }
    EXPECT_GT(checked, 64u * 48u / 2) << "the plane covers most of the view";
}

TEST_F(SkyLightTest, NothingOfAUniformSkyReachesInsideTheClosedRoom) {
    const float open = float(M_PI);  // the open plane's irradiance under radiance 1
    const std::vector<float> e = skyIrradiance(makeBuiltinScene("room"), uniformSky(1.0f));
    ASSERT_EQ(e.size(), 64u * 48u * 4u);
    float most = 0.0f;
    size_t surfaces = 0;
    for (size_t i = 0; i < e.size(); i += 4) {
        if (e[i + 3] < 0.5f) continue;
        ++surfaces;
        for (int c = 0; c < 3; ++c) most = std::max(most, e[i + c]);
    }
    EXPECT_EQ(surfaces, 64u * 48u) << "the room's walls fill the view";
    EXPECT_LE(most, 1e-3f * open);
}

// The light's rule of single-sided triangles (the shadow maps'), by the voxels' facing bits: a box
// whose fronts face inward around an open plane (a sky dome) lets the whole sky in, pi L as on the
// open plane and within that test's tolerance; the same box with its fronts facing outward (a closed
// shed) hides it all. The path tracer's answer is the same (sky_reference_test.cpp).
TEST_F(SkyLightTest, ASingleSidedEnclosureHidesTheSkyOnlyWhereItsFrontsFaceTheSky) {
    for (const bool inward : {true, false}) {
        const std::vector<float> e = skyIrradiance(enclosedPlane(inward), uniformSky(1.0f));
        ASSERT_EQ(e.size(), 64u * 48u * 4u);
        size_t checked = 0;
        for (size_t i = 0; i < e.size(); i += 4) {
            if (e[i + 3] < 0.5f || std::abs(position_[i / 4].y) > 0.05) continue;  // the plane's pixels
            ++checked;
            for (int c = 0; c < 3; ++c) {
                if (inward) EXPECT_NEAR(e[i + c], float(M_PI), 1e-3f) << "pixel " << i / 4;
                else EXPECT_LE(e[i + c], 1e-3f * float(M_PI)) << "pixel " << i / 4;
            }
        }
        EXPECT_EQ(checked, 64u * 48u) << "the plane fills the view (fronts " << (inward ? "inward)" : "outward)");
    }
}

TEST_F(SkyLightTest, TheSkyAovIsTheSkyLightsIrradiance) {
    // `--aov sky` shows the sky light's irradiance at every surface pixel, unchanged.
    RenderSettings s;
    s.aov = Aov::Sky;
    const std::vector<float> e = skyIrradiance(makeBuiltinScene("street"), uniformSky(1.0f), s);
    ASSERT_EQ(e.size(), direct_.size());
    size_t surfaces = 0;
    for (size_t i = 0; i < e.size(); i += 4) {
        if (normal_[i / 4] == glm::dvec3(0.0)) continue;  // the background
        ++surfaces;
        for (int c = 0; c < 3; ++c) EXPECT_EQ(direct_[i + c], e[i + c]) << "pixel " << i / 4;
    }
    EXPECT_GT(surfaces, 64u * 48u / 2);
}

TEST_F(SkyLightTest, WithoutVisibilityTheRoomSeesTheWholeSky) {
    // The same room with --sky-visibility none: the floor, facing up, gets the open plane's pi L, so
    // the closed room's darkness above is the occlusion's doing.
    RenderSettings s;
    s.skyLight.visibility = SkyVisibility::None;
    const std::vector<float> e = skyIrradiance(makeBuiltinScene("room"), uniformSky(1.0f), s);
    ASSERT_EQ(e.size(), 64u * 48u * 4u);
    float most = 0.0f;
    for (size_t i = 0; i < e.size(); i += 4) most = std::max(most, e[i + 1]);
    EXPECT_NEAR(most, float(M_PI), 1e-3f);
}

TEST_F(SkyLightTest, StreetSkyIrradianceAgreesWithTracedVisibility) {
    // The street under a uniform sky: every pixel's irradiance against the same sky's occlusion
    // traced by Embree (the path tracer's BVH), 1024 rays a pixel: within the sky-light target (0.10
    // relative L1) by the maps and by the voxels, and far better than no occlusion at all.
    const Scene scene = makeBuiltinScene("street");
    RenderSettings open;
    open.skyLight.visibility = SkyVisibility::None;
    const std::vector<float> none = skyIrradiance(scene, uniformSky(1.0f), open);
    for (const SkyVisibility visibility : {SkyVisibility::Maps, SkyVisibility::Voxels}) {
        RenderSettings s;
        s.skyLight.visibility = visibility;
        const std::vector<float> occluded = skyIrradiance(scene, uniformSky(1.0f), s);
        ASSERT_FALSE(occluded.empty());
        const reference::RayScene rays(scene);
        const float eps = 1e-4f * scene.bounds.radius();
        double err = 0.0, errNone = 0.0, sum = 0.0;
        for (size_t i = 0; i < position_.size(); ++i) {
            if (normal_[i] == glm::dvec3(0.0)) continue;
            const double traced = tracedSkyIrradiance(rays, position_[i], normal_[i], eps, 32);
            err += std::abs(occluded[i * 4 + 1] - traced);
            errNone += std::abs(none[i * 4 + 1] - traced);
            sum += traced;
        }
        ASSERT_GT(sum, 0.0);
        const char* name = visibility == SkyVisibility::Maps ? "maps" : "voxels";
        RecordProperty(std::string("rel_l1_") + name, std::to_string(err / sum));
        RecordProperty("rel_l1_none", std::to_string(errNone / sum));
        std::printf("street sky irradiance rel L1: %s %.4f, no occlusion %.4f\n", name, err / sum, errNone / sum);
        EXPECT_LT(err, 0.25 * errNone) << name;
        EXPECT_LE(err / sum, 0.10) << name;
    }
}

TEST_F(SkyLightTest, AMovingSunReweighsTheRaysWithoutTracingThemAgain) {
    // The street under its analytic sky; the sun turns between two frames of a still view. The
    // second frame weighs the first frame's clear rays (or looks up the first frame's maps) with the
    // new sky and traces (draws) nothing, and its irradiance equals that of a renderer that saw the
    // turned sun first.
    Scene scene = makeBuiltinScene("street");
    ASSERT_FALSE(scene.lights.empty());
    ASSERT_EQ(scene.lights[0].type, LightType::Directional);
    RenderSettings s;
    s.lighting.sky.kind = SkyKind::Analytic;
    s.width = 64, s.height = 48, s.giTemporal = false;
    FrameInputs frame{scene.cameras.at(0), scene.lights, {}, {}, {}};
    FrameInputs turned = frame;
    const glm::vec3 d = turned.lights[0].direction;
    turned.lights[0].direction = glm::normalize(glm::vec3(d.z, d.y, -d.x));  // 90 degrees about +Y
    auto passNames = [](const TestRenderer& r) {
        std::vector<std::string> names;
        for (const PassDesc& p : r.passes()) names.push_back(p.name);
        return names;
    };
    for (const SkyVisibility visibility : {SkyVisibility::Maps, SkyVisibility::Voxels}) {
        const bool maps = visibility == SkyVisibility::Maps;
        s.skyLight.visibility = visibility;
        TestRenderer moving(ctx(), scene, s);
        moving.render(frame);
        const std::vector<float> before = irradiance(moving);
        const std::vector<std::string> first = passNames(moving);
        EXPECT_EQ(std::count(first.begin(), first.end(), maps ? "sky.maps.setup" : "sky.trace"), 1);
        moving.render(turned);
        const std::vector<std::string> passes = passNames(moving);
        EXPECT_EQ(std::count(passes.begin(), passes.end(), maps ? "sky.maps.setup" : "sky.trace"), 0);
        EXPECT_EQ(std::count(passes.begin(), passes.end(), maps ? "sky.look" : "sky.weigh"), 1);
        const std::vector<float> after = irradiance(moving);
        TestRenderer fresh(ctx(), scene, s);
        fresh.render(turned);
        const std::vector<float> expected = irradiance(fresh);
        ASSERT_EQ(after.size(), expected.size());
        EXPECT_GT(relativeL1(after, before), 0.01) << "the turned sun changes the sky's light";
        EXPECT_LE(relativeL1(after, expected), 1e-6);
    }
}

TEST_F(SkyLightTest, GeometryMovingUnderAStillViewIsTracedAgainOverFourFrames) {
    // With the voxels, each of four frames traces one texel of every 2x2 block.
    slidingBoxCatchesUp(SkyVisibility::Voxels, "sky.trace", 4);
}

TEST_F(SkyLightTest, MovedGeometryDrawsTheMapsAgain) {
    // With the maps, the frame after the box moves draws every map again.
    slidingBoxCatchesUp(SkyVisibility::Maps, "sky.maps.setup", 1);
}

TEST(SkyVisibility, AutoTakesTheMapsUpToTheirBudgetAndTheRaysBeyond) {
    SkyLightSettings s;  // auto, 64 maps
    EXPECT_EQ(resolveSkyVisibility(s, 300000), SkyVisibility::Maps);
    EXPECT_EQ(resolveSkyVisibility(s, 300001), SkyVisibility::Voxels);
    s.mapCount = 32;  // half the maps: twice the triangles
    EXPECT_EQ(resolveSkyVisibility(s, 600000), SkyVisibility::Maps);
    s.visibility = SkyVisibility::Maps;  // asked for: kept
    EXPECT_EQ(resolveSkyVisibility(s, 100000000), SkyVisibility::Maps);
    s.visibility = SkyVisibility::None;
    EXPECT_EQ(resolveSkyVisibility(s, 1), SkyVisibility::None);
}
