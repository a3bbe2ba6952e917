// The temporal-GI module (src/temporal_gi): its history follows its model (a mean of the first frames,
// then an exponential average), restarts on a light's jump, forgets exactly the pixels that were not
// visible in the last frame, converges to the single-frame estimator's mean, and its spatial filter
// keeps the edges between surfaces. Contributions whose value the test knows exactly (the constant
// ambient of tests/ambient_technique.h, the RSM's exact all-texels sum) make each expectation exact.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/gtc/quaternion.hpp>

#include "ambient_technique.h"
#include "motion_test_util.h"
#include "scene/motion.h"
#include "temporal_gi/temporal_gi_technique.h"
#include "test_renderer.h"

namespace penumbra::test {
namespace {

class TemporalGiTest : public GpuTest {
protected:
    // The frame with the temporal accumulation off: the single-frame estimate.
    std::vector<float> singleFrame(const Scene& scene, RenderSettings s, const FrameInputs& in) {
        s.giTemporal = false;
        TestRenderer r(ctx(), scene, s);
        r.render(in);
        return r.readHdr();
    }
};

// Cornell at 64x48 with the RSM's exact sum (every texel of a 32^2 map: no sample pattern, the same
// value every frame), the indirect AOV, the history unfiltered.
RenderSettings exactRsm() {
    RenderSettings s;
    s.width = 64;
    s.height = 48;
    s.gi = GiMode::Rsm;
    s.rsm.mode = RsmMode::AllTexels;
    s.rsm.resolution = 32;
    s.aov = Aov::Indirect;
    s.temporalGi.filterIterations = 0;
    return s;
}

// The largest difference of the colour channels over the image, relative to the largest value of `b`.
double largestRelativeDifference(const std::vector<float>& a, const std::vector<float>& b) {
    double worst = 0.0, scale = 1e-30;
    for (size_t i = 0; i < a.size(); i += 4)
        for (int c = 0; c < 3; ++c) {
            worst = std::max(worst, double(std::abs(a[i + c] - b[i + c])));
            scale = std::max(scale, double(std::abs(b[i + c])));
        }
    return worst / scale;
}

TEST(TemporalGiChange, LightChangeWeightFollowsTheTurnAndTheRadiance) {
    Light sun;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    const std::vector<Light> before{sun};
    auto turned = [&](float degrees) {
        Light l = sun;
        const glm::vec3 axis = glm::normalize(glm::cross(sun.direction, glm::vec3(0, 0, 1)));  // a turn by `degrees`
        l.direction = glm::angleAxis(glm::radians(degrees), axis) * sun.direction;
        return std::vector<Light>{l};
    };
    EXPECT_FLOAT_EQ(lightChangeWeight(before, before, 5.0f, 10.0f), 0.0f);
    EXPECT_NEAR(lightChangeWeight(before, turned(1.5f), 5.0f, 10.0f), 0.0225f, 1e-4f);  // (1.5 / 10)^2
    EXPECT_NEAR(lightChangeWeight(before, turned(5.0f), 5.0f, 10.0f), 0.25f, 1e-3f);
    EXPECT_FLOAT_EQ(lightChangeWeight(before, turned(20.0f), 5.0f, 10.0f), 1.0f);  // a jump restarts
    Light brighter = sun, off = sun;
    brighter.intensity *= 1.1f;
    off.intensity = 0.0f;
    EXPECT_NEAR(lightChangeWeight(before, {brighter}, 5.0f, 10.0f), std::pow(0.1f / 1.1f / 0.5f, 2.0f), 1e-4f);
    EXPECT_FLOAT_EQ(lightChangeWeight(before, {off}, 5.0f, 10.0f), 1.0f);     // switched off
    EXPECT_FLOAT_EQ(lightChangeWeight({off}, before, 5.0f, 10.0f), 1.0f);     // switched on
    EXPECT_FLOAT_EQ(lightChangeWeight(before, {sun, sun}, 5.0f, 10.0f), 1.0f);  // a light added
}

TEST(TemporalGiChange, CameraCutIsAJumpNotAStep) {
    Camera c;
    Camera step = c, turn = c, jump = c;
    step.eye.x += 0.05f;
    step.target.x += 0.05f;
    turn.target = c.eye + glm::angleAxis(glm::radians(40.0f), glm::vec3(0, 1, 0)) * (c.target - c.eye);
    jump.eye.x += 3.0f;
    EXPECT_FALSE(cameraCut(c, step, 5.0f));
    EXPECT_TRUE(cameraCut(c, turn, 5.0f));
    EXPECT_TRUE(cameraCut(c, jump, 5.0f));
}

// The step response on a still view: an ambient irradiance switched from A to B after frame 5 (lights
// unchanged: no change is detected). The history is the mean of its first frames, then an exponential
// average at the least weight: frame n blends at alpha_n = max(1/n, minWeight), so frame k after the
// switch is I_B + prod_{j<=k} (1 - alpha_j) (I_A - I_B) at every pixel.
TEST_F(TemporalGiTest, StepResponseFollowsTheModel) {
    const Scene scene = makeBuiltinScene("cornell");
    RenderSettings s = exactRsm();
    s.temporalGi.minWeight = 0.25f;
    const FrameInputs in{scene.cameras[0], scene.lights};
    ambientSettings(s) = {true, 0.5f};
    const std::vector<float> a = singleFrame(scene, s, in);
    TestRenderer r(ctx(), scene, s);
    double keep = 1.0;  // the weight of A in the history
    std::vector<float> b;
    for (int n = 1; n <= 12; ++n) {
        if (n == 6) {
            ambientSettings(s).irradiance = 2.0f;
            b = singleFrame(scene, s, in);
            r.apply(s);
        }
        r.render(in);
        const double alpha = std::max(1.0 / n, double(s.temporalGi.minWeight));
        if (n >= 6) keep *= 1.0 - alpha;
        const std::vector<float> img = r.readHdr();
        std::vector<float> expected(img.size());
        for (size_t i = 0; i < img.size(); ++i)
            expected[i] = n < 6 ? a[i] : float(b[i] + keep * (double(a[i]) - b[i]));
        EXPECT_LT(largestRelativeDifference(img, expected), 1e-5) << "frame " << n;
    }
}

// A light that jumps (twice the intensity) restarts the history: that frame is the single-frame
// estimate, with the full sample count and the pattern of a single frame, bit for bit. The default
// RSM gather (sampled, its pattern changing from frame to frame while the history accumulates).
TEST_F(TemporalGiTest, ALightsJumpRestartsTheHistoryWithTheSingleFrameEstimate) {
    const Scene scene = makeBuiltinScene("cornell");
    RenderSettings s;
    s.width = 64;
    s.height = 48;
    s.gi = GiMode::Rsm;
    s.rsm.resolution = 128;
    s.aov = Aov::Indirect;
    s.temporalGi.filterIterations = 0;
    std::vector<Light> doubled = scene.lights;
    doubled[0].intensity *= 2.0f;
    TestRenderer r(ctx(), scene, s);
    for (int n = 0; n < 4; ++n) r.render(FrameInputs{scene.cameras[0], scene.lights});
    const std::vector<float> before = r.readHdr();
    r.render(FrameInputs{scene.cameras[0], doubled});
    const std::vector<float> single = singleFrame(scene, s, FrameInputs{scene.cameras[0], doubled});
    EXPECT_EQ(r.readHdr(), single);
    EXPECT_GT(largestRelativeDifference(before, single), 0.2) << "the light's change shows";
}

TEST_F(TemporalGiTest, AnotherGiModeRestartsTheHistory) {
    // Four RSM frames, then LPV through Renderer::apply (as the viewer and eval switch modes): the
    // LPV frame is LPV's single-frame estimate, with nothing of the RSM's history in it.
    const Scene scene = makeBuiltinScene("cornell");
    RenderSettings s = exactRsm();
    TestRenderer r(ctx(), scene, s);
    for (int n = 0; n < 4; ++n) r.render(FrameInputs{scene.cameras[0], scene.lights});
    const std::vector<float> rsm = r.readHdr();
    s.gi = GiMode::Lpv;
    r.apply(s);
    r.render(FrameInputs{scene.cameras[0], scene.lights});
    const std::vector<float> single = singleFrame(scene, s, FrameInputs{scene.cameras[0], scene.lights});
    EXPECT_LE(largestRelativeDifference(r.readHdr(), single), 1e-6);
    EXPECT_GT(largestRelativeDifference(rsm, single), 0.05) << "the two modes differ";
}

// The square at y = 1 slides along x at 1 m/s over the ground under a still camera, the frames 0.2 s
// apart (so that it uncovers a band of a few pixels); a constant
// ambient irradiance goes from 1 to 3 between the two frames. In the second frame a pixel whose
// surface point the last frame showed blends the two (alpha 1/2: (1 + 3) / 2), and one it did not
// show (ground the square covered a frame earlier) starts anew at 3: the ratio to the single-frame
// image is 2/3 or 1. Which pixel is which comes from the analytic scene, pixels within 3 cm of the
// square's edge (in either frame) left out. The visibility path (the square's pixels follow its motion
// through their IDs).
TEST_F(TemporalGiTest, DisocclusionRestartsExactlyTheDisoccludedPixels) {
    TempDir dir;
    const Scene scene = loadScene(slidingOccluder(dir));
    const Camera camera = lookingAt({0.0f, 3.0f, 3.0f}, {0.0f, 0.0f, 0.0f}, 50.0f);
    RenderSettings s = exactRsm();
    s.width = 96;
    s.height = 72;
    const double t = 0.5, dt = 0.2;
    GpuScene gpu(ctx(), scene);
    const SceneMotion motion(gpu.scene(), camera, gpu.scene().lights, {}, {});
    const ScenePose then = motion.at(t - dt), now = motion.at(t);
    ambientSettings(s) = {true, 1.0f};
    TestRenderer r(ctx(), gpu, s, 1);
    r.render(FrameInputs{camera, then.lights, then.instances});
    ambientSettings(s).irradiance = 3.0f;
    r.apply(s);
    FrameInputs second{camera, now.lights, now.instances};
    second.previous = FrameInputs::Previous{camera, then.instances};
    r.render(second);
    const std::vector<float> img = r.readHdr();
    RenderSettings single = s;
    single.giTemporal = false;
    TestRenderer reference(ctx(), gpu, single, 1);
    reference.render(second);
    const std::vector<float> fresh = reference.readHdr();

    const HorizontalSquare before{-0.5 + t - dt, 1.0, 0.0, 0.25}, after{-0.5 + t, 1.0, 0.0, 0.25};
    int disoccluded = 0, kept = 0;
    double worst = 0.0;
    for (uint32_t y = 0; y < s.height; ++y)
        for (uint32_t x = 0; x < s.width; ++x) {
            const Ray ray = cameraRay(camera, s.width, s.height, x, y);
            const auto top = hitHorizontalPlane(ray, 1.0), floorHit = hitHorizontalPlane(ray, 0.0);
            if (!top || !floorHit) continue;
            const dvec3 q = ray.origin + *top * ray.dir, g = ray.origin + *floorHit * ray.dir;
            if (before.boundaryDistance(q) < 0.03 || after.boundaryDistance(q) < 0.03) continue;
            if (std::abs(g.x) > 1.9 || std::abs(g.z) > 1.9) continue;
            const bool disoccludedNow = !after.contains(q) && before.contains(q);
            const size_t i = (size_t(y) * s.width + x) * 4;
            const double ratio = img[i + 1] / std::max(fresh[i + 1], 1e-30f);
            worst = std::max(worst, std::abs(ratio - (disoccludedNow ? 1.0 : 2.0 / 3.0)));
            (disoccludedNow ? disoccluded : kept) += 1;
        }
    std::printf("[ temporal disocclusion ] %d disoccluded and %d kept pixels, largest ratio error %.2e\n",
                disoccluded, kept, worst);
    EXPECT_GT(disoccluded, 10);
    EXPECT_GT(kept, 1000);
    EXPECT_LT(worst, 1e-4);
}


// Where the filter may take light from: a pixel's filtered value lies within the range of the
// unfiltered values of its own surface (the same normal within 1 degree and the same plane within 1 cm)
// inside the filter's reach (1 + 2 + 4 + 8 pixels for its four iterations), so no light crosses an edge
// between surfaces, not even to the pixel beside it. Cornell's first frame (a fresh history: only the
// geometry stops the filter) with the RSM's exact sum.
TEST_F(TemporalGiTest, FilterTakesNoLightAcrossAnEdge) {
    const Scene scene = makeBuiltinScene("cornell");
    RenderSettings s = exactRsm();
    const FrameInputs in{scene.cameras[0], scene.lights};
    auto frame = [&](Aov aov, uint32_t iterations) {
        RenderSettings f = s;
        f.aov = aov;
        f.temporalGi.filterIterations = iterations;
        TestRenderer r(ctx(), scene, f);
        r.render(in);
        return r.readHdr();
    };
    const std::vector<float> raw = frame(Aov::Indirect, 0), filtered = frame(Aov::Indirect, 4);
    const std::vector<float> normal = frame(Aov::Normal, 0), distance = frame(Aov::Depth, 0);
    const int w = int(s.width), h = int(s.height), reach = 15;
    auto position = [&](int x, int y) {
        const Ray ray = cameraRay(in.camera, s.width, s.height, x, y);
        return ray.origin + double(distance[(size_t(y) * w + x) * 4]) * ray.dir;
    };
    int checked = 0, changed = 0;
    double worst = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = (size_t(y) * w + x) * 4;
            if (normal[i + 3] == 0.0f) continue;  // background
            const dvec3 n(normal[i], normal[i + 1], normal[i + 2]), p = position(x, y);
            double lo = 1e30, hi = -1e30;
            for (int qy = std::max(0, y - reach); qy <= std::min(h - 1, y + reach); ++qy)
                for (int qx = std::max(0, x - reach); qx <= std::min(w - 1, x + reach); ++qx) {
                    const size_t j = (size_t(qy) * w + qx) * 4;
                    if (normal[j + 3] == 0.0f) continue;
                    const dvec3 m(normal[j], normal[j + 1], normal[j + 2]);
                    if (glm::dot(n, m) < std::cos(glm::radians(1.0)) || std::abs(glm::dot(n, position(qx, qy) - p)) > 0.01)
                        continue;
                    lo = std::min(lo, double(raw[j + 1]));
                    hi = std::max(hi, double(raw[j + 1]));
                }
            const double v = filtered[i + 1], tolerance = 2e-3 * std::max(hi, 1e-30);  // half floats
            worst = std::max(worst, std::max(lo - v, v - hi) / std::max(hi, 1e-30));
            changed += std::abs(v - raw[i + 1]) > tolerance;
            ++checked;
        }
    std::printf("[ temporal filter ] %d pixels, %d changed by the filter; the farthest outside its surface's "
                "range: %.2e of it\n", checked, changed, worst);
    EXPECT_GT(checked, 2000);
    EXPECT_GT(changed, checked / 4) << "the filter smooths";
    EXPECT_LT(worst, 2e-3);
}

// A still view converges to the single-frame estimator's mean, which for the unbiased default gather
// is the exact sum over every RSM texel (all-texels mode, at a 64^2 map). 64 accumulated frames of the
// default gather at every pixel (a new pattern each frame; the history an exact mean at minWeight 1/64), unfiltered,
// with two sample-pattern seeds: each is as close to the exact sum as their noise allows, within 1.5
// times the distance between the two over sqrt(2). (A mean of 64 single frames with seeds 1..64 does
// not converge there: their far samples, drawn by flux at each receiver's fixed shift, keep a fixed
// pattern per pixel.)
TEST_F(TemporalGiTest, StillViewConvergesToTheExactSum) {
    const Scene scene = makeBuiltinScene("cornell");
    RenderSettings s;
    s.width = 48;
    s.height = 36;
    s.gi = GiMode::Rsm;
    s.rsm.resolution = 64;
    s.rsm.mode = RsmMode::Full;  // every pixel gathers, as the exact sum does (no interpolation)
    s.aov = Aov::Indirect;
    s.temporalGi.filterIterations = 0;
    s.temporalGi.minWeight = 1.0f / 64.0f;
    const FrameInputs in{scene.cameras[0], scene.lights};
    RenderSettings all = s;
    all.rsm.mode = RsmMode::AllTexels;
    const std::vector<float> exact = singleFrame(scene, all, in);
    auto accumulated = [&](uint32_t seed) {
        RenderSettings one = s;
        one.rsm.seed = seed;
        TestRenderer r(ctx(), scene, one);
        for (int k = 0; k < 64; ++k) r.render(in);
        return r.readHdr();
    };
    const std::vector<float> a = accumulated(1), b = accumulated(2);
    auto relL1 = [&](const std::vector<float>& x, const std::vector<float>& y) {
        double num = 0.0, den = 0.0;
        for (size_t i = 0; i < x.size(); i += 4)
            for (int c = 0; c < 3; ++c) num += std::abs(double(x[i + c]) - y[i + c]), den += y[i + c];
        return num / den;
    };
    const double noise = relL1(a, b) / std::sqrt(2.0), errorA = relL1(a, exact), errorB = relL1(b, exact);
    std::printf("[ temporal convergence ] rel L1 to the exact sum after 64 frames: %.4f and %.4f; their noise "
                "%.4f\n", errorA, errorB, noise);
    EXPECT_GT(noise, 0.0);
    EXPECT_LT(errorA, 1.5 * noise);
    EXPECT_LT(errorB, 1.5 * noise);
}

}  // namespace
}  // namespace penumbra::test
