// The flicker figures of `penumbra stability` (src/app/stability.h) on sequences whose answer is known:
// a linear ramp in time has no second difference, a sequence that alternates has the largest, and
// the path tracer's noise is removed from the RMS figure by two independent renders.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "app/stability.h"

namespace penumbra {
namespace {

// `frames` images of `pixels` values: pixel i at frame t is base_i + slope_i t + wobble_i (-1)^t.
std::vector<std::vector<float>> sequence(int frames, int pixels, float wobble, uint32_t seed, float noise) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> gauss(0.0f, 1.0f);
    std::vector<std::vector<float>> out(static_cast<size_t>(frames), std::vector<float>(static_cast<size_t>(pixels)));
    for (int t = 0; t < frames; ++t)
        for (int i = 0; i < pixels; ++i) {
            const float base = 1.0f + 0.001f * float(i % 97), slope = 0.01f * float(i % 7);
            out[size_t(t)][size_t(i)] = base + slope * float(t) + (t % 2 ? -wobble : wobble) + noise * gauss(rng);
        }
    return out;
}

TEST(Flicker, SmoothMotionGivesZeroAndAlternationItsAmplitude) {
    EXPECT_NEAR(flicker(sequence(6, 1000, 0.0f, 1, 0.0f)), 0.0, 1e-6);
    // I_t - (I_{t-1} + I_{t+1}) / 2 = +-2 w for an alternation of amplitude w: the figure is 2 w / mean(I).
    const auto alternating = sequence(6, 1000, 0.05f, 1, 0.0f);
    double sum = 0.0;
    size_t n = 0;
    for (const auto& img : alternating)
        for (float v : img) sum += v, ++n;
    const double mean = sum / double(n);
    EXPECT_NEAR(flicker(alternating), 0.1 / mean, 1e-4);
    EXPECT_NEAR(flickerRms(alternating), 0.1 / mean, 1e-4);
}

TEST(Flicker, TwoIndependentRendersRemoveTheNoiseFromTheRmsFigure) {
    // Noise of sigma 0.05 per value adds sigma * sqrt(1.5) to every second difference: far more than the
    // wobble's 2 * 0.01. The product of two independent renders' differences leaves the wobble alone.
    const auto clean = sequence(8, 40000, 0.01f, 1, 0.0f);
    const auto a = sequence(8, 40000, 0.01f, 2, 0.05f), b = sequence(8, 40000, 0.01f, 3, 0.05f);
    const double truth = flickerRms(clean);
    EXPECT_GT(flickerRms(a), 2.5 * truth);  // the noisy figure is mostly noise
    EXPECT_NEAR(flickerRmsNoiseFree(a, b), truth, 0.05 * truth);
    EXPECT_NEAR(flickerRmsNoiseFree(clean, clean), truth, 1e-9);
}

}  // namespace
}  // namespace penumbra
