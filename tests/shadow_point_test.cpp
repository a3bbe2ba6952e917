// GPU tests of point-light shadows (cube maps and dual paraboloids) and of the shadow passes of
// every filter, on lavapipe with validation; the shadow options' error paths of the CLI.
#include <cmath>
#include <cstdio>
#include <set>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cli_run.h"
#include "shadow_test_util.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

constexpr double kRoom = 3.0;      // walls at distance 3 from the light, on every axis
constexpr double kOccluderAt = 1.2, kOccluderHalf = 0.35;

// Unit axis i (0..5: +x, -x, +y, -y, +z, -z) and two unit vectors perpendicular to it.
void axisFrame(int i, dvec3& a, dvec3& u, dvec3& v) {
    const int k = i / 2;
    const double sign = (i % 2) ? -1.0 : 1.0;
    a = dvec3(0.0);
    a[k] = sign;
    u = dvec3(0.0);
    u[(k + 1) % 3] = 1.0;
    v = glm::cross(a, u);
}

// A room of 6 inward-facing walls around a point light at the origin, one single-sided square facing
// the light on each axis (single-sided: a pipeline with the wrong winding would cull it and lose its shadow).
Scene sixAxesScene() {
    Scene s;
    s.name = "six-axes";
    const uint32_t wall = addMaterial(s, glm::vec3(0.6f)), block = addMaterial(s, glm::vec3(0.8f));
    for (int i = 0; i < 6; ++i) {
        dvec3 a, u, v;
        axisFrame(i, a, u, v);
        // Quad corner + edges so that cross(edgeU, edgeV) = -a (faces the light) for both.
        auto square = [&](double dist, double half, uint32_t m) {
            const glm::vec3 c(a * dist - (u + v) * half);
            addQuad(s, c, glm::vec3(v * (2.0 * half)), glm::vec3(u * (2.0 * half)), m);
        };
        square(kRoom, kRoom, wall);
        square(kOccluderAt, kOccluderHalf, block);
    }
    Light point;
    point.type = LightType::Point;
    point.position = {0.0f, 0.0f, 0.0f};
    point.direction = {0.0f, -1.0f, 0.0f};  // paraboloid axis: +-y; +-x and +-z lie on the seam
    point.intensity = 10.0f;
    s.lights.push_back(point);
    s.computeBounds();
    return s;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Point light: each of the six occluders casts its shadow (the square scaled by 3 / 1.2) on its
// wall, for cube maps and for dual paraboloids (whose seam the x and z occluders straddle).
// ---------------------------------------------------------------------------------------------
TEST_F(ShadowGpuTest, PointLightOccludersOnAllSixAxesCastTheirShadows) {
    constexpr uint32_t W = 96, H = 96;
    const Scene scene = sixAxesScene();
    for (PointShadowMode mode : {PointShadowMode::Cube, PointShadowMode::Paraboloid}) {
        const bool cube = mode == PointShadowMode::Cube;
        ShadowSettings settings;
        settings.resolution = 256;
        settings.pointMode = mode;
        for (int i = 0; i < 6; ++i) {
            dvec3 a, u, v;
            axisFrame(i, a, u, v);
            SCOPED_TRACE(fmt::format("{}, axis {}", cube ? "cube" : "paraboloid", i));
            Camera cam;  // inside the room, off the axis, looking at the wall's centre
            cam.eye = glm::vec3(-0.5 * a + 1.6 * u + 1.6 * v);
            cam.target = glm::vec3(kRoom * a);
            cam.up = glm::vec3(v);
            cam.fovy = glm::radians(70.0f);
            const Frame frame = renderFrame(scene, cam, W, H, Aov::Shadow, settings);
            const FloatImage depth = renderFrame(scene, cam, W, H, Aov::Depth, settings).image;
            const double texel = frame.layers.at(0).projection.texelSize;  // per unit distance (largest)
            auto wallHit = [&](const Ray& ray) -> std::optional<double> {
                const double d = glm::dot(ray.dir, a);
                if (d <= 1e-9) return std::nullopt;
                const double t = (kRoom - glm::dot(ray.origin, a)) / d;
                const dvec3 p = ray.origin + t * ray.dir;
                if (std::abs(glm::dot(p, u)) > kRoom - 0.05 || std::abs(glm::dot(p, v)) > kRoom - 0.05) return std::nullopt;
                return t;
            };
            const ShadowStats stats = judgeShadow(frame.image, depth, cam, wallHit, [&](const dvec3& p) {
                const dvec3 q = p * (kOccluderAt / kRoom);  // the ray from the light at the occluder's plane
                const double du = kOccluderHalf - std::abs(glm::dot(q, u)), dv = kOccluderHalf - std::abs(glm::dot(q, v));
                ShadowTruth t;
                t.shadowed = du >= 0.0 && dv >= 0.0;
                t.edgeDistance = (t.shadowed ? std::min(du, dv) : std::hypot(std::min(du, 0.0), std::min(dv, 0.0))) *
                                 (kRoom / kOccluderAt);
                // 3 texels at the wall, stretched by the incidence on it.
                const double cosIncidence = kRoom / glm::length(p);
                t.band = 3.0 * texel * glm::length(p) / cosIncidence;
                return t;
            });
            reportShadow(fmt::format("{} axis {}", cube ? "cube" : "paraboloid", i), stats, 100);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The Cornell box with a point light, every filter and both point modes: validation silent, values
// in [0, 1], and the filter's passes in the timings (moments only for the moment filters).
// ---------------------------------------------------------------------------------------------
TEST_F(ShadowGpuTest, EveryFilterReportsItsPassesOnCornellWithAPointLight) {
    Scene scene = makeBuiltinScene("cornell");
    Light point;
    point.type = LightType::Point;
    point.position = {0.2f, 1.6f, 0.3f};
    point.intensity = 3.0f;
    scene.lights.push_back(point);  // beside the spot light: two shadowed lights, two kinds
    for (PointShadowMode mode : {PointShadowMode::Cube, PointShadowMode::Paraboloid})
        for (ShadowFilter f : {ShadowFilter::Hard, ShadowFilter::Pcf, ShadowFilter::Pcss, ShadowFilter::Vsm,
                               ShadowFilter::Evsm, ShadowFilter::Msm}) {
            SCOPED_TRACE(fmt::format("{} {}", mode == PointShadowMode::Cube ? "cube" : "paraboloid",
                                     shadowFilterName(f)));
            ShadowSettings s;
            s.resolution = 128;
            s.filter = f;
            s.pointMode = mode;
            const Frame frame = renderFrame(scene, scene.cameras[0], 64, 48, Aov::Shadow, s);
            EXPECT_EQ(frame.layers.size(), mode == PointShadowMode::Cube ? 7u : 3u);
            size_t bad = 0, dark = 0;
            for (size_t i = 0; i < frame.image.rgba.size(); i += 4) {
                const float v = frame.image.rgba[i];
                bad += !(v >= 0.0f && v <= 1.0f);
                dark += v < 0.5f;
            }
            EXPECT_EQ(bad, 0u);
            EXPECT_GT(dark, 0u);  // the boxes shadow something
            std::set<std::string> names;
            for (const vk::ScopeTiming& t : frame.timings) names.insert(t.name);
            EXPECT_TRUE(names.count("shadow.map") && names.count("shadow.filter"));
            EXPECT_EQ(names.count("shadow.moments") + names.count("shadow.blur"), usesMoments(f) ? 2u : 0u);
        }
}

// ---------------------------------------------------------------------------------------------
// CLI: every bad shadow option value gives one "penumbra: error:" line and a non-zero exit.
// ---------------------------------------------------------------------------------------------
TEST(ShadowCliErrors, BadValuesGiveOneErrorLine) {
    const std::vector<std::string> bad = {"--shadow soft",       "--cascades 9",        "--cascades 0",
                                          "--csm-lambda 1.5",    "--csm-blend 0.9",     "--point-shadow sphere",
                                          "--pcf-radius -1",     "--vsm-bleed 1",       "--vsm-blur 33",
                                          "--pcss-light-size 0", "--light-shadow 3=pcf", "--light-shadow 0=soft",
                                          "--light-shadow pcf",  "--raster gpu"};
    const ScratchDir dir("shadow_cli");
    for (const std::string& args : bad)
        expectRefused(dir, fmt::format("render cornell -o {} --width 8 --height 8 {}", dir.file("out.png"), args));
}
