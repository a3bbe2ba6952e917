// The RSM's temporal gradients (names::kGiChange) and the history weight that follows them: last
// frame's kept receivers gathered again with their own pattern measure exactly zero under a still
// light and exactly the light's ratio under a brighter one; under a light that keeps growing, the
// history lags as its model says (temporal_gi/accumulate.comp).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "temporal_gradient.h"

namespace penumbra::test {
namespace {

// Cornell at 64x48, the default RSM gather (low resolution, interpolated), unfiltered indirect light.
RenderSettings cornellRsm() {
    RenderSettings s = unfilteredIndirect(GiMode::Rsm);
    s.rsm.resolution = 128;
    return s;
}

std::vector<Gradient> rsmChange(TestRenderer& r) { return readChange(r, r.rsmGather()->change()); }

TEST_F(GpuTest, RsmGradientOfAStillLightIsZero) {
    const Scene scene = makeBuiltinScene("cornell");
    TestRenderer r(ctx(), scene, cornellRsm());
    for (int n = 0; n < 3; ++n) r.render(FrameInputs{scene.cameras[0], scene.lights});
    const std::vector<Gradient> g = rsmChange(r);
    int measured = 0, nonzero = 0;
    for (const Gradient& t : g) {
        if (t.measured != 1.0f) continue;
        ++measured;
        nonzero += t.change != 0.0f || t.larger <= 0.0f;
    }
    std::printf("[ rsm gradient ] still light: %d of %zu blocks measured, %d not exactly 0\n", measured, g.size(),
                nonzero);
    EXPECT_GT(measured, int(g.size()) / 2);
    EXPECT_EQ(nonzero, 0);
}

// A light 5% brighter: the gather is linear in the RSM's flux, so every kept sample's luminance grows
// by 1.05, and change / larger = 1 - 1 / 1.05 = 0.0476. Up to rounding: the RSM holds its flux in half
// floats (2^-11 relative), and a texel drawn by flux near a step of the CDF may change; so the median
// within 1e-4 and every sample within 5e-3 (a tenth of the change).
TEST_F(GpuTest, RsmGradientOfABrighterLightIsItsRatio) {
    const Scene scene = makeBuiltinScene("cornell");
    TestRenderer r(ctx(), scene, cornellRsm());
    for (int n = 0; n < 2; ++n) r.render(FrameInputs{scene.cameras[0], scene.lights});
    r.render(FrameInputs{scene.cameras[0], scaled(scene.lights, 1.05f)});
    const double expected = 1.0 - 1.0 / 1.05;
    std::vector<double> ratios;
    for (const Gradient& t : rsmChange(r))
        if (t.measured == 1.0f && t.larger > 0.0f) ratios.push_back(t.change / t.larger);
    ASSERT_GT(ratios.size(), 20u);
    std::sort(ratios.begin(), ratios.end());
    const double median = ratios[ratios.size() / 2];
    std::printf("[ rsm gradient ] 5%% brighter: %zu samples, median change %.6f (expected %.6f), range %.6f .. "
                "%.6f\n", ratios.size(), median, expected, ratios.front(), ratios.back());
    EXPECT_NEAR(median, expected, 1e-4);
    EXPECT_NEAR(ratios.front(), expected, 5e-3);
    EXPECT_NEAR(ratios.back(), expected, 5e-3);
}

// A light that grows by 5% a frame for 16 frames: with the gradients the history keeps up to within
// about lagTolerance / 2 (the model's 0.95 at 0.1), without them (a tolerance of 1000) it holds about
// half of the light. The image's mean against the single-frame estimate at the last intensity, and
// against the model with the exact change 1 - 1 / 1.05.
TEST_F(GpuTest, HistoryFollowsAGrowingLightAsItsModelSays) {
    const GrowingLightShares r = growingLightShares(ctx(), makeBuiltinScene("cornell"), [](float lagTolerance) {
        RenderSettings s = cornellRsm();
        s.rsm.lagTolerance = lagTolerance;
        return s;
    }, "rsm");
    EXPECT_NEAR(r.withGradients, r.modelWith, 0.01);
    EXPECT_NEAR(r.without, r.modelWithout, 0.01);
    EXPECT_GT(r.modelWith, 0.93);
}

}  // namespace
}  // namespace penumbra::test
