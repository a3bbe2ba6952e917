// What the temporal-gradient tests of the GI techniques share: the change image (core/names.h
// GiChange) read back, a light made brighter, and the history's model under a light that keeps growing
// (temporal_gi/accumulate.comp).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "test_renderer.h"

namespace penumbra::test {

// A change texel: (change of luminance, larger luminance, change^2 / larger, 1 where measured).
struct Gradient {
    float change, larger, squared, measured;
};

inline std::vector<Gradient> readChange(TestRenderer& r, vk::Image& image) {
    const std::vector<uint8_t> bytes = r.commands().readImage(image, sizeof(Gradient));
    std::vector<Gradient> out(size_t(image.width()) * image.height());
    std::memcpy(out.data(), bytes.data(), out.size() * sizeof(Gradient));
    return out;
}

// 64x48 frames of `gi` whose output is the unfiltered indirect light: what the gradient tests read.
inline RenderSettings unfilteredIndirect(GiMode gi) {
    RenderSettings s;
    s.width = 64;
    s.height = 48;
    s.gi = gi;
    s.aov = Aov::Indirect;
    s.temporalGi.filterIterations = 0;
    return s;
}

inline std::vector<Light> scaled(std::vector<Light> lights, float factor) {
    for (Light& l : lights) l.intensity *= factor;
    return lights;
}

// The mean indirect light of an image.
inline double meanGreen(const std::vector<float>& img) {
    double sum = 0.0;
    for (size_t i = 1; i < img.size(); i += 4) sum += img[i];
    return sum / double(img.size() / 4);
}

// The history's share of its light under a light that grows by g per frame, frame n blending at
// alpha_n = max(1 / frames, minWeight, (host's change weight), detected / lagTolerance), frames the
// history's span (accumulate.comp): h_n / I_n after `frames` frames.
inline double modelShare(int frames, double g, double minWeight, double detected, double lagTolerance) {
    const double change = 1.0 - 1.0 / g, host = std::pow(change / 0.5, 2.0);  // temporal_gi_technique.cpp
    double share = 1.0, span = 1.0;  // the first frame starts the history
    for (int n = 2; n <= frames; ++n) {
        const double alpha = std::max({1.0 / (span + 1.0), minWeight, host, std::min(detected / lagTolerance, 1.0)});
        share = alpha + (1.0 - alpha) * share / g;
        span = 1.0 / alpha;
    }
    return share;
}

// The mean indirect light after `frames` frames of a light growing by g per frame (frame n at
// g^(n - 1)); without a history (s.giTemporal off) only the last frame is rendered: the truth.
inline double meanUnderGrowingLight(vk::Context& ctx, const Scene& scene, const RenderSettings& s, int frames,
                                    double g) {
    TestRenderer r(ctx, scene, s);
    for (int n = s.giTemporal ? 1 : frames; n <= frames; ++n)
        r.render(FrameInputs{scene.cameras[0], scaled(scene.lights, float(std::pow(g, n - 1)))});
    return meanGreen(r.readHdr());
}

// The history's share of the truth after 16 frames of a light growing 5% a frame, with a technique's
// gradients read at a tolerance of 0.1 and without them (1000), beside the model of each with the exact
// change 1 - 1 / 1.05. `settingsAt(tolerance)` makes the technique's settings at that tolerance.
struct GrowingLightShares {
    double withGradients, without, modelWith, modelWithout;
};

inline GrowingLightShares growingLightShares(vk::Context& ctx, const Scene& scene,
                                             const std::function<RenderSettings(float)>& settingsAt,
                                             const std::string& technique) {
    const int frames = 16;
    const double g = 1.05, detected = 1.0 - 1.0 / g;
    auto run = [&](float lagTolerance, bool temporal) {
        RenderSettings s = settingsAt(lagTolerance);
        s.giTemporal = temporal;
        return meanUnderGrowingLight(ctx, scene, s, frames, g);
    };
    const double truth = run(0.1f, false);
    const GrowingLightShares out{run(0.1f, true) / truth, run(1000.0f, true) / truth,
                                 modelShare(frames, g, 0.05, detected, 0.1), modelShare(frames, g, 0.05, detected, 1000.0)};
    std::printf("[ %s gradient ] light growing 5%% a frame, history / truth after %d frames: %.4f (model %.4f) "
                "with the gradients, %.4f (model %.4f) without\n", technique.c_str(), frames, out.withGradients,
                out.modelWith, out.without, out.modelWithout);
    return out;
}

}  // namespace penumbra::test
