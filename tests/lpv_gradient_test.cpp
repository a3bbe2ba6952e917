// The LPV's temporal gradients (lpv/gradient.comp, names::kGiChange): the irradiance of each block's
// centre receiver from the kept volume of last frame and from this frame's. The LPV has no sampling
// noise, so a still light measures exactly zero and a brighter one exactly its ratio; under a light
// that keeps growing, the history then keeps up as its model says (temporal_gi/accumulate.comp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "lpv_cpu_gather.h"
#include "lpv_volume.h"
#include "temporal_gradient.h"

namespace penumbra::test {
namespace {

// 64x48, LPV with a small RSM, unfiltered indirect light.
RenderSettings smallLpv() {
    RenderSettings s = unfilteredIndirect(GiMode::Lpv);
    s.lpv.rsmResolution = 256;
    s.lpv.vplResolution = 64;
    return s;
}

std::vector<Gradient> lpvChange(TestRenderer& r) { return readChange(r, r.lpv()->change()); }

// The luminance of the LPV's irradiance image at each change block's centre pixel (gradient.comp).
std::vector<float> centreLuminance(TestRenderer& r) {
    vk::Image& image = r.lpv()->irradiance();
    const std::vector<uint8_t> bytes = r.commands().readImage(image, sizeof(glm::vec4));
    const uint32_t block = LPV_CHANGE_BLOCK, w = (image.width() + block - 1) / block;
    const uint32_t h = (image.height() + block - 1) / block;
    std::vector<float> out;
    for (uint32_t by = 0; by < h; ++by)
        for (uint32_t bx = 0; bx < w; ++bx) {
            const uint32_t x = std::min(bx * block + block / 2, image.width() - 1);
            const uint32_t y = std::min(by * block + block / 2, image.height() - 1);
            glm::vec4 e;
            std::memcpy(&e, bytes.data() + (size_t(y) * image.width() + x) * sizeof(glm::vec4), sizeof(e));
            out.push_back(0.2126f * e.r + 0.7152f * e.g + 0.0722f * e.b);
        }
    return out;
}

// Whether the last frame measured (and published) the gradients.
bool ranGradient(const TestRenderer& r) {
    const std::vector<PassDesc>& passes = r.passes();
    return std::any_of(passes.begin(), passes.end(), [](const PassDesc& p) { return p.name == "lpv.gradient"; });
}

// Each still frame measures exactly 0 (bit-identical volumes). The first frame and a frame that restarts
// the history (a light three times as bright) measure nothing; the frame after a restart measures
// against the restarting frame's volume.
TEST_F(GpuTest, LpvGradientOfAStillLightIsZero) {
    const Scene scene = makeBuiltinScene("cornell");
    TestRenderer r(ctx(), scene, smallLpv());
    int measured = 0, nonzero = 0;
    size_t blocks = 0;
    auto count = [&] {
        const std::vector<Gradient> g = lpvChange(r);
        blocks += g.size();
        for (const Gradient& t : g) {
            if (t.measured != 1.0f) continue;
            ++measured;
            nonzero += t.change != 0.0f || t.squared != 0.0f || t.larger <= 0.0f;
        }
    };
    r.render(FrameInputs{scene.cameras[0], scene.lights});
    EXPECT_FALSE(ranGradient(r)) << "the first frame has no kept volume";
    for (int n = 0; n < 2; ++n) {
        r.render(FrameInputs{scene.cameras[0], scene.lights});
        EXPECT_TRUE(ranGradient(r));
        count();
    }
    const std::vector<Light> brighter = scaled(scene.lights, 3.0f);
    r.render(FrameInputs{scene.cameras[0], brighter});
    EXPECT_FALSE(ranGradient(r)) << "a frame that restarts the history";
    r.render(FrameInputs{scene.cameras[0], brighter});
    EXPECT_TRUE(ranGradient(r)) << "the frame after a restart";
    count();
    std::printf("[ lpv gradient ] still light, 3 frames: %d of %zu blocks measured, %d not exactly 0\n", measured,
                blocks, nonzero);
    EXPECT_GT(measured, int(blocks) / 2);
    EXPECT_EQ(nonzero, 0);
}

// A light 5% brighter: the LPV is linear in the light's flux (injection, propagation and gather all
// are), so every receiver's luminance grows by 1.05, and change / larger = 1 - 1 / 1.05 = 0.0476. Up
// to rounding only: the injection's 64-bit fixed-point sums keep 2^-31 of each cell's largest
// coefficient, and the float steps round at 2^-24 an operation over some hundred operations, both
// relative to terms that partly cancel in the SH dot products, so a receiver's luminance can be off
// by some 1e-5 of itself (3e-5 here at most); the ratio's error is about that: the median within 1e-4,
// every receiver within 1e-3. The change's two luminances are the gather's images of the two frames
// at the block's centre pixel (the same function of the same volumes).
TEST_F(GpuTest, LpvGradientOfABrighterLightIsItsRatio) {
    const Scene scene = makeBuiltinScene("cornell");
    TestRenderer r(ctx(), scene, smallLpv());
    for (int n = 0; n < 2; ++n) r.render(FrameInputs{scene.cameras[0], scene.lights});
    const std::vector<float> before = centreLuminance(r);
    r.render(FrameInputs{scene.cameras[0], scaled(scene.lights, 1.05f)});
    const std::vector<float> now = centreLuminance(r);
    const std::vector<Gradient> g = lpvChange(r);
    ASSERT_EQ(g.size(), now.size());
    const double expected = 1.0 - 1.0 / 1.05;
    std::vector<double> ratios;
    double worstImage = 0.0;  // the largest relative difference from the gather's images
    for (size_t i = 0; i < g.size(); ++i) {
        const Gradient& t = g[i];
        if (t.measured != 1.0f || t.larger <= 0.0f) continue;
        ratios.push_back(t.change / t.larger);
        worstImage = std::max({worstImage, std::abs(t.larger - now[i]) / double(now[i]),
                               std::abs(t.larger - t.change - before[i]) / double(before[i])});
    }
    ASSERT_GT(ratios.size(), 20u);
    std::sort(ratios.begin(), ratios.end());
    const double median = ratios[ratios.size() / 2];
    std::printf("[ lpv gradient ] 5%% brighter: %zu blocks, median change %.7f (expected %.7f), range %.7f .. "
                "%.7f; against the gathered images %.2g\n", ratios.size(), median, expected, ratios.front(),
                ratios.back(), worstImage);
    EXPECT_NEAR(median, expected, 1e-4);
    EXPECT_NEAR(ratios.front(), expected, 1e-3);
    EXPECT_NEAR(ratios.back(), expected, 1e-3);
    EXPECT_LT(worstImage, 1e-5);
}

// The luminance of the CPU gather (lpv_cpu_gather.h) of a summed volume at `placement`, at a
// receiver turned towards the eye as lpv/irradiance.glsl turns it.
double cpuLuminance(const std::vector<glm::vec4>& accum, const gpu::LpvPush& placement, const glm::vec3& eye,
                    const gpu::PixelProbe& at) {
    const glm::dvec3 x(at.position);
    glm::dvec3 n = glm::normalize(glm::dvec3(at.normal));
    if (glm::dot(n, glm::dvec3(eye) - x) < 0.0) n = -n;
    const double weights[3] = {0.2126, 0.7152, 0.0722};
    double sum = 0.0;
    for (int ch = 0; ch < 3; ++ch) sum += weights[ch] * lpv_cpu::gatherIrradiance(accum, placement, x, n, ch);
    return sum;
}

// In a city the cascades follow the camera: after a move of 1.5 finest cells, last frame's light is
// read at last frame's placement. A block's "before" luminance (now - change) is the CPU gather of the
// volume read back after the first frame, at the first frame's placement, at the block's centre
// receiver of the second frame (the probe's position and normal); read at the second frame's placement
// the same volume is clearly off.
TEST_F(GpuTest, LpvGradientReadsTheKeptVolumeAtItsOwnPlacement) {
    const Scene scene = makeBuiltinScene("street");
    RenderSettings s = smallLpv();
    const Camera first = scene.cameras[0];
    const glm::uvec2 block(3, 3), pixel = block * uint32_t(LPV_CHANGE_BLOCK) + uint32_t(LPV_CHANGE_BLOCK / 2);
    TestRenderer r(ctx(), scene, s);
    r.render(FrameInputs{first, scene.lights});
    const gpu::LpvPush before = r.lpv()->constants();
    const vk::Buffer& sum = r.lpv()->accumulated();
    const std::vector<glm::vec4> kept = asVec4(r.commands().readBuffer(sum, sum.size()));
    Camera second = first;
    const glm::vec3 move(1.5f * before.cascades[0].cellSize, 0.0f, 0.0f);
    second.eye += move;
    second.target += move;
    FrameInputs in{second, scene.lights};
    in.probePixel = pixel;
    r.render(in);
    ASSERT_TRUE(ranGradient(r));
    const gpu::LpvPush now = r.lpv()->constants();
    ASSERT_NE(now.cascades[0].origin.x, before.cascades[0].origin.x) << "the finest cascade moved";
    ASSERT_TRUE(r.probe() && r.probe()->surface == 1u);
    const std::vector<Gradient> g = lpvChange(r);
    const Gradient& t = g[block.y * r.lpv()->change().width() + block.x];
    ASSERT_EQ(t.measured, 1.0f);
    const double gpuBefore = t.change >= 0.0f ? t.larger - t.change : t.larger;
    const double cpuBefore = cpuLuminance(kept, before, second.eye, *r.probe());
    const double misplaced = cpuLuminance(kept, now, second.eye, *r.probe());
    std::printf("[ lpv gradient ] camera moved 1.5 cells: kept light %.6g on the GPU, %.6g on the CPU at its own "
                "placement, %.6g at the new one; now %.6g\n", gpuBefore, cpuBefore, misplaced, t.larger);
    EXPECT_NEAR(gpuBefore, cpuBefore, 1e-4 * cpuBefore);
    EXPECT_GT(std::abs(misplaced - cpuBefore), 0.05 * cpuBefore);
}

// A light that grows by 5% a frame for 16 frames: with the gradients (each texel measures the exact
// 1 - 1 / 1.05, with no spread to discount) the history keeps up as the model says with that change
// detected (0.95 at a tolerance of 0.1); without them (a tolerance of 1000) it holds clearly less.
TEST_F(GpuTest, LpvHistoryFollowsAGrowingLightAsItsModelSays) {
    const GrowingLightShares r = growingLightShares(ctx(), makeBuiltinScene("cornell"), [](float lagTolerance) {
        RenderSettings s = smallLpv();
        s.lpv.lagTolerance = lagTolerance;
        return s;
    }, "lpv");
    EXPECT_NEAR(r.withGradients, r.modelWith, 0.01);
    EXPECT_NEAR(r.without, r.modelWithout, 0.01);
    EXPECT_GT(r.withGradients - r.without, 0.15);
}

}  // namespace
}  // namespace penumbra::test
