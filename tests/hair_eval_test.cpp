// Hair against the path tracer (src/eval/hair_eval.*, docs/evaluation.md), lavapipe with
// validation: the renderer's hair coverage as alpha and the path tracer's area-sampled pixel give
// the same pixel, a w / p, for strands far thinner than a pixel (analytic); deep shadow maps give
// the reference's floor transmittance under the hair scene, which hair drawn opaque into an ordinary
// shadow map does not.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "eval/hair_eval.h"
#include "gpu_fixture.h"
#include "reference/path_tracer.h"
#include "scene/builders.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

constexpr double kPi = 3.14159265358979323846;

ReferenceSettings antialiased(uint32_t w, uint32_t h, uint32_t spp) {
    ReferenceSettings s;
    s.width = w, s.height = h, s.spp = spp, s.bounces = 0, s.antialias = true;
    s.threads = 2;
    s.progress = false;
    return s;
}

class HairEvalTest : public GpuTest {
protected:
    ImageF renderGpu(const Scene& scene, RenderSettings s, Aov aov) {
        s.aov = aov;
        Renderer r(ctx(), scene, s);
        r.render(scene.cameras[0]);
        return {s.width, s.height, r.readHdr()};
    }
};

}  // namespace

// Strands 0.1 pixel wide and 2.5 pixels apart, opacity 0.8, over the plane under an unshadowed sun,
// seen from straight above, each tilted by one pixel across the measured columns (so that its offset
// in the pixel rows takes every phase). A pixel's hair alpha is coverage x opacity: over the region,
// the sum over the 10 strands of a (w / p) / cos(tilt) (times the widening off the axis) / 25 rows. The renderer draws them one pixel wide with that alpha;
// the path tracer stops that fraction of its area-sampled paths. The renderer's alpha is read from
// its own images: (with - without) / (opaque wide strands - without).
TEST_F(HairEvalTest, SubPixelStrandsCoverTheirAreaTimesOpacity) {
    const uint32_t size = 48, x0 = 10, x1 = 38, y0 = 11, y1 = 36;  // columns |x| < 4.72, rows z in [-13, 12) px
    const double height = 1.0, pixel = 2.0 * (15.0 - height) * std::tan(kPi / 6.0) / size;  // at the strands
    const double a = 0.8, width = 0.1 * pixel, spacing = 2.5 * pixel, slope = 1.0 / (x1 - x0);
    auto strands = [&](double w, double opacity) {
        Scene s = makeBuiltinScene("plane");
        s.lights[0].castsShadow = false;
        Strand style;
        style.width = float(w), style.opacity = float(opacity), style.color = {0.9f, 0.2f, 0.1f};
        for (int k = -5; k < 5; ++k) {  // at x = 0: z / pixel = 2.5 k + 0.75
            const double z = (k + 0.3) * spacing;
            const glm::vec3 points[] = {{-5.0f, float(height), float(z - 5.0 * slope)},
                                        {5.0f, float(height), float(z + 5.0 * slope)}};
            addStrand(s, points, style);
        }
        return s;
    };
    const Scene thin = strands(width, a);
    RenderSettings rs;
    rs.width = rs.height = size;
    const ImageF with = renderGpu(thin, rs, Aov::Final), without = renderGpu(withoutStrands(thin), rs, Aov::Final);
    const ImageF opaque = renderGpu(strands(1.04 * spacing, 1.0), rs, Aov::Final);
    const ReferenceImage ref = renderReference(thin, thin.cameras[0], antialiased(size, size, 256));
    double gpuSum = 0.0, refSum = 0.0;
    for (uint32_t y = y0; y < y1; ++y)
        for (uint32_t x = x0; x < x1; ++x) {
            const size_t i = (size_t(y) * size + x) * 4;
            gpuSum += (with.rgba[i] - without.rgba[i]) / (opaque.rgba[i] - without.rgba[i]);
            refSum += ref.hair[i / 4];
        }
    const double n = double((x1 - x0) * (y1 - y0));
    // A ribbon facing the eye at z off the axis (depth D) is sqrt(1 + (z / D)^2) times wider on the
    // image than at the centre (f w sqrt(D^2 + z^2) / D^2).
    double expected = 0.0;
    for (int k = -5; k < 5; ++k) {
        const double z = (k + 0.3) * spacing, depth = 15.0 - height;
        expected += a * width / pixel * std::sqrt(1.0 + z * z / (depth * depth)) * std::sqrt(1.0 + slope * slope);
    }
    expected /= double(y1 - y0);
    EXPECT_NEAR(gpuSum / n, expected, 0.01 * expected) << "the renderer's mean hair alpha";
    // Each reference path stops at a strand or not: a Bernoulli mean over n x 256 paths.
    const double se = std::sqrt(expected * (1.0 - expected) / (n * 256.0));
    EXPECT_NEAR(refSum / n, expected, 4.5 * se) << "the path tracer's mean hair alpha";
}

// The hair scene (1000 strands) at 128x96: the floor's transmittance under the hair (shadow AOV with
// / without the strands) from deep shadow maps is the path tracer's; with the hair drawn opaque into
// an ordinary PCF shadow map the floor under it is far too dark.
TEST_F(HairEvalTest, DeepShadowMapsGiveTheReferenceFloorTransmittance) {
    BuiltinOptions options;
    options.hairStrands = 1000;
    const Scene scene = makeBuiltinScene("hair", options);
    const Camera& camera = scene.cameras[0];
    const uint32_t w = 128, h = 96;
    const ReferenceImage ref = renderReference(scene, camera, antialiased(w, h, 32));
    const ReferenceImage bare = renderReference(withoutStrands(scene), camera, antialiased(w, h, 32));
    RenderSettings base;
    base.width = w, base.height = h;
    base.shadow.resolution = 1024;
    const HairGroundTruth truth = makeHairGroundTruth(
        {w, h, ref.rgba(ReferenceAov::Final)}, ref.covered, {w, h, ref.rgba(ReferenceAov::Hair)},
        {w, h, ref.rgba(ReferenceAov::Shadow)}, {w, h, bare.rgba(ReferenceAov::Shadow)},
        floorPixels(ctx(), scene, camera, base), ref.relativeNoise(ReferenceAov::Final));
    const size_t measured = size_t(std::count(truth.shadowPixels.begin(), truth.shadowPixels.end(), uint8_t(1)));
    ASSERT_GT(measured, 50u) << "floor pixels in the hair's shadow";
    std::vector<EvalVariant> variants;
    for (const EvalVariant& v : hairEvalVariants(base))
        if (v.technique == "shadow pcf" || v.technique == "shadow dsm") variants.push_back(v);
    ASSERT_EQ(variants.size(), 2u);
    const std::vector<HairEvalRow> rows = runHairEval(ctx(), scene, camera, variants, truth, 1, nullptr);
    const HairEvalRow &pcf = rows[0], &dsm = rows[1];
    for (const HairEvalRow& r : rows) EXPECT_TRUE(r.warnings.empty()) << r.variant.technique << ": " << r.warnings[0];
    std::printf("[ hair eval ] %zu floor pixels, reference mean T %.3f; dsm: T L2 %.3f, bias %+.4f; pcf: T L2 %.3f, "
                "bias %+.3f; hair L2 dsm %.3f pcf %.3f\n", measured, dsm.transmittance.refMean,
                dsm.transmittance.relL2, dsm.transmittance.meanBias, pcf.transmittance.relL2,
                pcf.transmittance.meanBias, dsm.hair.relL2, pcf.hair.relL2);
    // A DSM stores the strands' transmittance per texel: its mean over the shadow is the reference's.
    EXPECT_LT(std::abs(dsm.transmittance.meanBias), 0.02);
    EXPECT_LT(dsm.transmittance.relL2, 0.15);
    // Opaque hair in a shadow map leaves a fraction of the light (gaps between ribbons at most).
    EXPECT_LT(pcf.transmittance.meanBias, -0.3);
    EXPECT_LT(dsm.hair.relL2, pcf.hair.relL2) << "the hair itself is lit through the DSM";
}
