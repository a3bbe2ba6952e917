// GPU tests of the shadow-map family on lavapipe with validation (gpu_fixture.h): every filter
// against the analytic shadow of a square occluder away from its penumbra, PCSS penumbra width
// against the blocker-distance formula, cascade stability under sub-texel camera moves, VSM light
// bleeding and its reduction. Point lights: shadow_point_test.cpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <set>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "scene/builders.h"
#include "shadow_test_util.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

const ShadowFilter kAllFilters[] = {ShadowFilter::Hard, ShadowFilter::Pcf, ShadowFilter::Pcss,
                                    ShadowFilter::Vsm,  ShadowFilter::Evsm, ShadowFilter::Msm};

constexpr double kPlaneHalf = 4.0;
const HorizontalSquare kOccluder{-0.4, 1.0, 0.1, 0.75};

Scene occluderScene(const Light& light) {
    Scene s;
    s.name = "shadow-occluder";
    addQuad(s, {-kPlaneHalf, 0, -kPlaneHalf}, {0, 0, 2 * kPlaneHalf}, {2 * kPlaneHalf, 0, 0}, addMaterial(s, glm::vec3(0.5f)));
    addHorizontalSquare(s, kOccluder, addMaterial(s, glm::vec3(0.8f)));
    s.lights.push_back(light);
    s.computeBounds();
    return s;
}

Camera obliqueCamera() {
    Camera c;
    c.eye = {0.0f, 4.5f, 2.6f};
    c.target = {-0.1f, 0.0f, 0.4f};
    c.fovy = glm::radians(45.0f);
    return c;
}

// How far (in shadow texels, perpendicular to the light) a filter may soften an edge, PCSS aside.
double filterReachTexels(const ShadowSettings& s) {
    switch (s.filter) {
        case ShadowFilter::Pcf: return s.pcfRadius + 2.0;
        case ShadowFilter::Vsm:
        case ShadowFilter::Evsm:
        case ShadowFilter::Msm: return s.blurRadius + 2.5;
        default: return 2.0;
    }
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Every filter, directional (4 cascades) and spot: away from the penumbra, a pixel is lit (>= 0.9)
// exactly where the analytic projection of the occluder says so, and shadowed (<= 0.1) elsewhere.
// ---------------------------------------------------------------------------------------------
TEST_F(ShadowGpuTest, EveryFilterMatchesAnalyticOccluderAwayFromPenumbra) {
    constexpr uint32_t W = 160, H = 120;
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.45f, -1.0f, 0.3f));
    sun.intensity = 3.0f;
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0.3f, 4.0f, 0.6f};
    spot.direction = glm::normalize(glm::vec3(-0.3f, 0.0f, 0.2f) - spot.position);
    spot.intensity = 20.0f;
    spot.innerConeAngle = glm::radians(38.0f);
    spot.outerConeAngle = glm::radians(45.0f);
    const Camera cam = obliqueCamera();
    for (const Light& light : {sun, spot}) {
        const bool isSpot = light.type == LightType::Spot;
        const Scene scene = occluderScene(light);
        ShadowSettings base;
        base.resolution = 512;
        base.pcssLightSize = 0.15f;
        base.pcssSunAngle = 3.0f;
        const FloatImage depth = renderFrame(scene, cam, W, H, Aov::Depth, base).image;
        for (ShadowFilter f : kAllFilters) {
            ShadowSettings s = base;
            s.filter = f;
            SCOPED_TRACE(fmt::format("{} light, {}", isSpot ? "spot" : "directional", shadowFilterName(f)));
            const Frame frame = renderFrame(scene, cam, W, H, Aov::Shadow, s);
            double texel = 0.0;  // largest texel of the light's layers (world units; spot: per unit depth)
            for (const ShadowLayer& l : frame.layers) texel = std::max(texel, double(l.projection.texelSize));
            const dvec3 lpos(light.position), axis = glm::normalize(dvec3(light.direction));
            const ShadowStats stats = compareShadow(frame.image, depth, cam, kPlaneHalf, [&](const dvec3& p) {
                ShadowTruth t;
                const dvec3 toLight = isSpot ? glm::normalize(lpos - p) : -axis;
                const dvec3 q = p + toLight * ((kOccluder.y - p.y) / toLight.y);  // along the ray, at occluder height
                t.shadowed = kOccluder.contains(q);
                // Distances in the occluder plane grow by Ly / (Ly - h) on the plane for a spot light.
                const double spread = isSpot ? lpos.y / (lpos.y - kOccluder.y) : 1.0;
                t.edgeDistance = kOccluder.boundaryDistance(q) * spread;
                const double texelHere = isSpot ? texel * glm::dot(p - lpos, axis) : texel;
                double reach = filterReachTexels(s) * texelHere;
                if (f == ShadowFilter::Pcss) {  // half the penumbra w = (d_r - d_b) * size / d_b (spot)
                    const double rayToOccluder = kOccluder.y / toLight.y;
                    const double w = isSpot ? s.pcssLightSize * kOccluder.y / (lpos.y - kOccluder.y)
                                            : rayToOccluder * 2.0 * std::tan(glm::radians(0.5 * s.pcssSunAngle));
                    reach = std::min(0.5 * w, s.pcssMaxRadius * texelHere) + 2.0 * texelHere;
                }
                t.band = reach / toLight.y;  // perpendicular to the ray -> on the plane
                if (isSpot)  // only where the light is at full strength (inside the inner cone)
                    t.compare = std::acos(std::clamp(glm::dot(-toLight, axis), -1.0, 1.0)) < spot.innerConeAngle - 0.01;
                return t;
            });
            reportShadow(fmt::format("{} {}", isSpot ? "spot" : "sun", shadowFilterName(f)), stats);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// PCSS: a blocker edge (height 2) straight below the light, receivers at heights 0 and 1. For a
// spot light at height 4 the formula w = (d_r - d_b) * size / d_b, for a sun straight above
// w = (d_r - d_b) * 2 tan(angle / 2): both predict penumbra widths in the ratio (2 - 0) / (2 - 1) = 2.
// Measured: the 10%-90% width of the visibility profile across the edge on each receiver.
// ---------------------------------------------------------------------------------------------
namespace {

constexpr double kLightY = 4.0, kBlockerY = 2.0, kPlatformY = 1.0;

Scene pcssSteps(const Light& light) {
    Scene s;
    s.name = "pcss-steps";
    const uint32_t grey = addMaterial(s, glm::vec3(0.5f));
    addQuad(s, {-3, 0, 0}, {0, 0, 3}, {6, 0, 0}, grey);                      // ground, z in [0, 3]
    addQuad(s, {-3, float(kPlatformY), -3}, {0, 0, 2.8f}, {6, 0, 0}, grey);  // platform, z in [-3, -0.2]
    addQuad(s, {-4, float(kBlockerY), -3.5f}, {0, 0, 7}, {4, 0, 0}, grey);   // blocker, x <= 0
    s.lights.push_back(light);
    s.computeBounds();
    return s;
}

// 10%-90% widths of the visibility profile across x = 0 on the ground and on the platform.
std::array<double, 2> penumbraWidths(const FloatImage& vis, const FloatImage& depth, const Camera& cam) {
    struct Receiver {
        double y, zMin, zMax;
        EdgeProfile profile;
    };
    Receiver receivers[] = {{0.0, 0.3, 2.7, EdgeProfile(-0.8, 0.8, 0.01)},
                            {kPlatformY, -2.7, -0.5, EdgeProfile(-0.8, 0.8, 0.01)}};
    for (uint32_t y = 0; y < vis.height; ++y)
        for (uint32_t x = 0; x < vis.width; ++x)
            for (Receiver& r : receivers) {
                const Ray ray = cameraRay(cam, vis.width, vis.height, x, y);
                const std::optional<double> t = hitHorizontalPlane(ray, r.y);
                if (!t || std::abs(depth.at(x, y) - *t) > 1e-3 * *t) continue;
                const dvec3 p = ray.origin + *t * ray.dir;
                if (p.z >= r.zMin && p.z <= r.zMax) r.profile.add(p.x, vis.at(x, y));
            }
    return {receivers[0].profile.width(0.1, 0.9), receivers[1].profile.width(0.1, 0.9)};
}

}  // namespace

TEST_F(ShadowGpuTest, PcssPenumbraWidthFollowsBlockerDistance) {
    constexpr uint32_t W = 240, H = 240;
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0.0f, float(kLightY), 0.0f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.outerConeAngle = glm::radians(70.0f);
    spot.innerConeAngle = glm::radians(65.0f);
    Light sun;
    sun.direction = {0.0f, -1.0f, 0.0f};
    Camera cam;
    cam.eye = {3.0f, 8.0f, 0.0f};  // beside the blocker's edge, so that it hides little of the receivers
    cam.target = {0.0f, 0.0f, 0.0f};
    cam.up = {0.0f, 0.0f, -1.0f};
    cam.fovy = glm::radians(45.0f);
    ShadowSettings settings;
    settings.resolution = 1024;
    settings.filter = ShadowFilter::Pcss;
    settings.pcssLightSize = 0.5f;
    settings.pcssSunAngle = 8.0f;
    for (const Light& light : {spot, sun}) {
        const bool isSpot = light.type == LightType::Spot;
        const Scene s = pcssSteps(light);
        const FloatImage vis = renderFrame(s, cam, W, H, Aov::Shadow, settings).image;
        const FloatImage depth = renderFrame(s, cam, W, H, Aov::Depth, settings).image;
        const std::array<double, 2> width = penumbraWidths(vis, depth, cam);
        // Full penumbra widths by the formula (vertical rays: distances are height differences).
        const double scale = isSpot ? settings.pcssLightSize / (kLightY - kBlockerY)
                                    : 2.0 * std::tan(glm::radians(0.5 * settings.pcssSunAngle));
        const double predictedRatio = kBlockerY / (kBlockerY - kPlatformY);
        const double ratio = width[0] / width[1];
        std::printf("[pcss %s] 10-90%% penumbra width: ground %.4f, platform %.4f (formula: full penumbra %.4f, "
                    "%.4f); ratio %.3f, predicted %.3f (%.1f%% off)\n",
                    isSpot ? "spot" : "sun", width[0], width[1], scale * kBlockerY, scale * (kBlockerY - kPlatformY),
                    ratio, predictedRatio, 100.0 * std::abs(ratio / predictedRatio - 1.0));
        RecordProperty(isSpot ? "spot_width_ratio" : "sun_width_ratio", fmt::format("{:.3f}", ratio));
        EXPECT_GT(width[1], 0.0);
        EXPECT_NEAR(ratio / predictedRatio, 1.0, 0.2) << (isSpot ? "spot" : "sun");
    }
}

// ---------------------------------------------------------------------------------------------
// CSM stability: a top-down camera moves by exactly one pixel's ground footprint (a fraction of a
// shadow texel); pixel x of the new image shows the ground point pixel x + 1 of the old one did.
// With texel snapping its shadow must not change (< 0.1% of pixels); without, edges crawl.
// ---------------------------------------------------------------------------------------------
TEST_F(ShadowGpuTest, CascadesDoNotShimmerWhenTheCameraMoves) {
    constexpr uint32_t W = 240, H = 240;
    Scene s;
    s.name = "csm-field";
    const uint32_t grey = addMaterial(s, glm::vec3(0.5f));
    addQuad(s, {-20, 0, -20}, {0, 0, 40}, {40, 0, 0}, grey);
    // Occluders rotated 30 degrees: slanted edges, whose staircases show any shift of the texel grid.
    const glm::vec3 u{std::cos(0.5236f), 0.0f, -std::sin(0.5236f)}, v{std::sin(0.5236f), 0.0f, std::cos(0.5236f)};
    for (int i = -3; i <= 3; ++i)
        for (int j = -3; j <= 3; ++j)
            addQuad(s, glm::vec3(2.3f * i, 1.5f, 2.3f * j) - 0.5f * u - 0.5f * v, v, u, grey);
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.5f));
    s.lights.push_back(sun);
    s.computeBounds();
    Camera a;
    a.eye = {0.0f, 12.0f, 0.0f};
    a.target = {0.0f, 0.0f, 0.0f};
    a.up = {0.0f, 0.0f, -1.0f};  // image x = world x
    a.fovy = glm::radians(60.0f);
    const float pixel = 2.0f * 12.0f * std::tan(0.5f * a.fovy) / float(W);
    Camera b = a;
    b.eye.x += pixel;
    b.target.x += pixel;

    for (ShadowFilter f : {ShadowFilter::Hard, ShadowFilter::Vsm}) {
        for (bool stabilize : {true, false}) {
            ShadowSettings settings;
            settings.resolution = 256;
            settings.filter = f;
            settings.cascades.stabilize = stabilize;
            const Frame fa = renderFrame(s, a, W, H, Aov::Shadow, settings);
            const Frame fb = renderFrame(s, b, W, H, Aov::Shadow, settings);
            const FloatImage da = renderFrame(s, a, W, H, Aov::Depth, settings).image;
            const FloatImage db = renderFrame(s, b, W, H, Aov::Depth, settings).image;
            std::string texels;  // the move in texels of each cascade
            for (const ShadowLayer& l : fa.layers) texels += fmt::format(" {:.2f}", pixel / l.projection.texelSize);
            size_t compared = 0, changed = 0;
            for (uint32_t y = 0; y < H; ++y)
                for (uint32_t x = 0; x + 1 < W; ++x) {
                    const double floorDistance = *hitHorizontalPlane(cameraRay(b, W, H, x, y), 0.0);
                    if (std::abs(db.at(x, y) - floorDistance) > 1e-3 * floorDistance ||
                        std::abs(da.at(x + 1, y) - floorDistance) > 1e-3 * floorDistance)
                        continue;  // an occluder in front in either image
                    ++compared;
                    changed += std::abs(fb.image.at(x, y) - fa.image.at(x + 1, y)) > 1.0f / 255.0f;
                }
            const double percent = 100.0 * double(changed) / double(compared);
            std::printf("[csm] %s, %s: camera moved %.4f (texels of cascades 0-3:%s): %zu of %zu ground pixels "
                        "changed (%.3f%%)\n",
                        shadowFilterName(f).c_str(), stabilize ? "snapped" : "NOT snapped", pixel, texels.c_str(),
                        changed, compared, percent);
            EXPECT_GT(compared, size_t(W) * H / 4);
            if (stabilize) EXPECT_LT(percent, 0.1) << shadowFilterName(f);
            else EXPECT_GT(percent, 0.3) << "the test should see shimmering without snapping";
        }
    }
}

// ---------------------------------------------------------------------------------------------
// VSM light bleeding (Donnelly & Lauritzen 2006): a large occluder B just above the ground and a
// small one A high above part of it, light straight down. Everything under B is in its umbra, but
// where A's outline crosses the filter window the window holds two depths: their variance makes
// the Chebyshev bound leak light onto the receiver (A's outline shows inside B's shadow). The
// reduction (linstep(amount, 1, p)) must cut that leak down.
// ---------------------------------------------------------------------------------------------
TEST_F(ShadowGpuTest, VsmBleedingReductionReducesLightBleeding) {
    constexpr uint32_t W = 200, H = 150;
    Scene s;
    s.name = "vsm-bleeding";
    addQuad(s, {-4, 0, -4}, {0, 0, 8}, {8, 0, 0}, addMaterial(s, glm::vec3(0.5f)));
    const HorizontalSquare low{0.0, 0.3, 0.0, 1.5}, high{0.9, 3.0, 0.2, 0.4};
    addHorizontalSquare(s, low, addMaterial(s, glm::vec3(0.8f)));
    addHorizontalSquare(s, high, addMaterial(s, glm::vec3(0.8f)));
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {0.0f, -1.0f, 0.0f};
    s.lights.push_back(sun);
    s.computeBounds();
    Camera cam;  // low, so that it sees a strip of ground under the low occluder's edge
    cam.eye = {5.0f, 1.5f, 0.3f};
    cam.target = {1.0f, 0.0f, 0.2f};
    cam.fovy = glm::radians(35.0f);
    ShadowSettings base;
    base.resolution = 512;
    base.filter = ShadowFilter::Vsm;
    const FloatImage depth = renderFrame(s, cam, W, H, Aov::Depth, base).image;
    struct Leak {
        double mean = 0, max = 0;
        size_t pixels = 0;
    };
    auto measure = [&](const ShadowSettings& settings) {
        const FloatImage vis = renderFrame(s, cam, W, H, Aov::Shadow, settings).image;
        Leak leak;
        for (uint32_t y = 0; y < H; ++y)
            for (uint32_t x = 0; x < W; ++x) {
                const Ray ray = cameraRay(cam, W, H, x, y);
                const double t = hitHorizontalPlane(ray, 0.0).value_or(-1.0);
                if (t <= 0.0 || std::abs(depth.at(x, y) - t) > 1e-3 * t) continue;
                const dvec3 p = ray.origin + t * ray.dir;
                if (!low.contains(p) || low.boundaryDistance(p) < 0.15) continue;  // B's umbra, off its edges
                leak.mean += vis.at(x, y);
                leak.max = std::max(leak.max, double(vis.at(x, y)));
                ++leak.pixels;
            }
        leak.mean /= double(std::max<size_t>(leak.pixels, 1));
        return leak;
    };
    // Bleeding against the reduction amount, then EVSM and MSM (no reduction) for comparison.
    std::vector<Leak> vsm;
    for (float amount : {0.0f, 0.2f, 0.4f, 0.7f}) {
        ShadowSettings settings = base;
        settings.bleedReduction = amount;
        vsm.push_back(measure(settings));
        std::printf("[vsm bleeding] reduction %.1f: in the low occluder's umbra (%zu px) mean visibility %.4f, max %.3f\n",
                    amount, vsm.back().pixels, vsm.back().mean, vsm.back().max);
    }
    for (ShadowFilter f : {ShadowFilter::Evsm, ShadowFilter::Msm}) {
        ShadowSettings settings = base;
        settings.filter = f;
        settings.bleedReduction = 0.0f;
        const Leak leak = measure(settings);
        std::printf("[vsm bleeding] %s, no reduction: mean visibility %.4f, max %.3f\n", shadowFilterName(f).c_str(),
                    leak.mean, leak.max);
    }
    RecordProperty("leak_none", fmt::format("{:.4f}", vsm.front().mean));
    RecordProperty("leak_0.7", fmt::format("{:.4f}", vsm.back().mean));
    EXPECT_GT(vsm.front().pixels, 500u);
    EXPECT_GT(vsm.front().max, 0.2) << "the scene should show VSM light bleeding";
    for (size_t i = 1; i < vsm.size(); ++i) EXPECT_LT(vsm[i].mean, vsm[i - 1].mean) << "reduction step " << i;
    EXPECT_LT(vsm.back().mean, 0.1 * vsm.front().mean);
    EXPECT_LT(vsm.back().max, 0.25 * vsm.front().max);
}
