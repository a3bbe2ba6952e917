// Helpers of the shadow GPU tests (shadow_test.cpp, shadow_point_test.cpp): a fixture that renders
// with given shadow settings and keeps the shadow layers, analytic comparison of a `shadow` AOV,
// and a visibility profile across a straight shadow edge.
#pragma once
#include <algorithm>
#include <cstdio>
#include <functional>
#include <vector>

#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "scene/builders.h"

namespace penumbra::test {

class ShadowGpuTest : public GpuTest {
protected:
    struct Frame {
        FloatImage image;
        std::vector<ShadowLayer> layers;
        std::vector<vk::ScopeTiming> timings;
    };

    Frame renderFrame(const Scene& scene, const Camera& camera, uint32_t width, uint32_t height, Aov aov,
                      const ShadowSettings& shadow) {
        RenderSettings settings;
        settings.width = width;
        settings.height = height;
        settings.aov = aov;
        settings.shadow = shadow;
        TestRenderer renderer(ctx(), scene, settings);
        renderer.setPassScopes(true);  // the result's per-pass timings
        renderer.render(camera);
        return {{width, height, renderer.readHdr()}, renderer.shadow().layers(), renderer.timings()};
    }
};

// A square parallel to y = 0, facing +y (single-sided).
inline void addHorizontalSquare(Scene& s, const HorizontalSquare& q, uint32_t material) {
    const float h = float(q.half);
    addQuad(s, {float(q.cx) - h, float(q.y), float(q.cz) - h}, {0, 0, 2 * h}, {2 * h, 0, 0}, material);
}

struct ShadowTruth {
    bool compare = true;      // false: outside the region the test judges
    bool shadowed = false;
    double edgeDistance = 0;  // world distance on the receiver to the analytic shadow edge
    double band = 0;          // pixels closer than this to the edge are the penumbra: not judged
};

struct ShadowStats {
    size_t compared = 0, matched = 0, shadowed = 0, shadowedMatched = 0, lit = 0, nearEdge = 0, other = 0;
    double fraction() const { return compared ? double(matched) / double(compared) : 0.0; }
    double shadowedFraction() const { return shadowed ? double(shadowedMatched) / double(shadowed) : 0.0; }
};

// Judges a pixel: lit means visibility >= 0.9, shadowed <= 0.1 (filters must reach both away from
// the penumbra). `receiver` gives the pixel's analytic receiver hit (distance along the ray), or
// nothing when the pixel is not judged; the depth AOV must agree (else another surface is in front).
inline ShadowStats judgeShadow(const FloatImage& shadow, const FloatImage& depth, const Camera& cam,
                               const std::function<std::optional<double>(const Ray&)>& receiver,
                               const std::function<ShadowTruth(const dvec3&)>& truth) {
    ShadowStats s;
    for (uint32_t y = 0; y < shadow.height; ++y)
        for (uint32_t x = 0; x < shadow.width; ++x) {
            const Ray ray = cameraRay(cam, shadow.width, shadow.height, x, y);
            const std::optional<double> t = receiver(ray);
            if (!t) continue;
            if (std::abs(depth.at(x, y) - *t) > 1e-3 * *t) {
                ++s.other;
                continue;
            }
            const ShadowTruth tr = truth(ray.origin + *t * ray.dir);
            if (!tr.compare) continue;
            if (tr.edgeDistance <= tr.band) {
                ++s.nearEdge;
                continue;
            }
            ++s.compared;
            (tr.shadowed ? s.shadowed : s.lit)++;
            const float v = shadow.at(x, y);
            if (tr.shadowed ? v <= 0.1f : v >= 0.9f) ++s.matched, s.shadowedMatched += tr.shadowed;
        }
    return s;
}

// The plane y = 0, |x|, |z| <= planeHalf (pixels showing anything in front of it are left out).
inline ShadowStats compareShadow(const FloatImage& shadow, const FloatImage& depth, const Camera& cam,
                                 double planeHalf, const std::function<ShadowTruth(const dvec3&)>& truth) {
    auto receiver = [&](const Ray& ray) -> std::optional<double> {
        const std::optional<double> t = hitHorizontalPlane(ray, 0.0);
        if (!t) return std::nullopt;
        const dvec3 p = ray.origin + *t * ray.dir;
        if (std::abs(p.x) > planeHalf || std::abs(p.z) > planeHalf) return std::nullopt;
        return t;
    };
    return judgeShadow(shadow, depth, cam, receiver, truth);
}

inline void reportShadow(const std::string& label, const ShadowStats& s, size_t minimum = 300) {
    std::printf("[%s] %zu/%zu pixels match (%.3f%%; shadowed %zu/%zu); left out: %zu in the penumbra band, %zu "
                "behind other surfaces\n",
                label.c_str(), s.matched, s.compared, 100.0 * s.fraction(), s.shadowedMatched, s.shadowed,
                s.nearEdge, s.other);
    EXPECT_GE(s.fraction(), 0.995) << label;
    EXPECT_GE(s.shadowedFraction(), 0.99) << label;
    EXPECT_GT(s.shadowed, minimum) << label << ": too little shadow in view to judge";
    EXPECT_GT(s.lit, minimum) << label;
}

// Mean visibility in bins of x across a shadow edge parallel to z.
class EdgeProfile {
public:
    EdgeProfile(double x0, double x1, double bin) : x0_(x0), bin_(bin), sum_(size_t((x1 - x0) / bin) + 1), n_(sum_.size()) {}
    void add(double x, double v) {
        if (x < x0_) return;
        const size_t i = size_t((x - x0_) / bin_);
        if (i < sum_.size()) sum_[i] += v, ++n_[i];
    }
    // Distance between the first crossings of `lo` and `hi` (the profile rises from shadow to light).
    double width(double lo, double hi) const { return crossing(hi) - crossing(lo); }

private:
    double crossing(double level) const {
        double prevX = 0.0, prevV = -1.0;
        for (size_t i = 0; i < sum_.size(); ++i) {
            if (n_[i] == 0) continue;
            const double x = x0_ + (i + 0.5) * bin_, v = sum_[i] / n_[i];
            if (v >= level) return prevV < 0.0 ? x : prevX + (level - prevV) / (v - prevV) * (x - prevX);
            prevX = x, prevV = v;
        }
        return x0_ + sum_.size() * bin_;
    }
    double x0_, bin_;
    std::vector<double> sum_;
    std::vector<size_t> n_;
};

}  // namespace penumbra::test
