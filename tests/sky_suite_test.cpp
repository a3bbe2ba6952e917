// The suite's sky cases (eval/sky_suite.h, `eval --suite --suite-cases sky`) against computations
// that do not go through them: the sky alone is the same sky with the lights off; a uniform sky
// over an open plane lights it with albedo x L; on the street the sky's direct term is the difference
// of renders and of references with and without the sky; and the sun-only figures are what the
// suite's sun-only evaluation gives.
#include <cmath>

#include <gtest/gtest.h>

#include "app/eval_suite_cli.h"
#include "core/gpu_scene.h"
#include "gpu_fixture.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

constexpr uint32_t kWidth = 40, kHeight = 24, kSpp = 16;

GroundTruth truthOf(const Scene& scene, const Camera& cam, const SkySettings& sky, uint64_t seed = 1) {
    ReferenceSettings s;
    s.width = kWidth, s.height = kHeight, s.spp = kSpp, s.seed = seed, s.progress = false, s.sky = sky;
    const ReferenceImage img = renderReference(scene, cam, s);
    GroundTruth t{{kWidth, kHeight, img.rgba(ReferenceAov::Direct)}, {kWidth, kHeight, img.rgba(ReferenceAov::Indirect)},
                  {}, std::vector<uint8_t>(img.covered)};
    t.final = t.direct;  // as the suite's cached references add them
    for (size_t k = 0; k < t.final.rgba.size(); ++k) t.final.rgba[k] += t.indirect.rgba[k];
    return t;
}

SkySettings uniformSky(float radiance) {
    SkySettings sky;
    sky.kind = SkyKind::Uniform;
    sky.uniformRadiance = glm::vec3(radiance);
    return sky;
}

// The renderer's direct radiance (its own AOV, not final - indirect) of `settings` after one frame.
ImageF renderedDirect(vk::Context& ctx, const Scene& scene, const Camera& cam, RenderSettings settings) {
    GpuScene gpuScene(ctx, scene);
    settings.aov = Aov::Direct;
    Renderer r(ctx, gpuScene, settings, 1);
    r.render(cam);
    return {settings.width, settings.height, r.readHdr()};
}

ImageF difference(const ImageF& a, const ImageF& b) {
    ImageF d = a;
    for (size_t k = 0; k < d.rgba.size(); ++k) d.rgba[k] -= b.rgba[k];
    return d;
}

}  // namespace

TEST(SkySuite, SkyAloneIsTheSameSkyWithTheLightsOff) {
    const Scene street = makeBuiltinScene("street");
    const SkySettings sky = suiteSky();
    const std::vector<Light> lights = skyOnlyLights(street.lights);
    std::vector<std::string> warnings;
    const Sky full = makeSky(sky, street.lights, warnings), alone = makeSky(skyOnlySky(sky, street.lights), lights, warnings);
    ASSERT_TRUE(alone.enabled());
    for (const glm::vec3 d : {glm::vec3(0, 1, 0), glm::vec3(0.6f, 0.3f, -0.2f), glm::vec3(-0.9f, 0.1f, 0.4f),
                              -street.lights[0].direction})
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(alone.radiance(glm::normalize(d))[c], full.radiance(glm::normalize(d))[c],
                        1e-6f * full.radiance(glm::normalize(d))[c]);
    ASSERT_EQ(street.lights.at(0).type, LightType::Directional);
    ASSERT_GT(street.lights[0].intensity, 0.0f);
    for (const Light& l : lights) EXPECT_EQ(l.intensity, 0.0f) << "the sun lights nothing directly";
    // Without its own sun's illuminance, the analytic sky of a light at intensity 0 is black.
    EXPECT_EQ(makeSky(sky, lights, warnings).radiance(glm::vec3(0, 1, 0)), glm::vec3(0.0f));
    // A sky that follows no light: the sky as given.
    EXPECT_EQ(skyOnlySky(uniformSky(1.0f), street.lights), uniformSky(1.0f));
    EXPECT_TRUE(hasSkyCase("sponza") && hasSkyCase("vc") && !hasSkyCase("cornell"));
}

// A uniform sky of radiance 1 over the open plane (albedo 0.5), the plane's sun off: the path
// tracer's direct light of the sky alone is albedo x 1 = 0.5 (irradiance pi).
TEST(SkySuite, SkyAloneOfAUniformSkyOverAnOpenPlaneIsAlbedo) {
    const Scene plane = makeBuiltinScene("plane");
    const SkySettings sky = uniformSky(1.0f);
    Scene alone = plane;
    alone.lights = skyOnlyLights(plane.lights);
    const GroundTruth t = truthOf(alone, plane.cameras.at(0), skyOnlySky(sky, plane.lights));
    const ImageF half{kWidth, kHeight, std::vector<float>(size_t(kWidth) * kHeight * 4, 0.5f)};
    const ImageMetrics m = compareImages(t.direct, half, t.mask);
    ASSERT_GT(m.pixels, 100u);
    EXPECT_LT(std::abs(relativeBias(m)), 0.02);
    EXPECT_LT(compareImages(t.indirect, ImageF{kWidth, kHeight, std::vector<float>(half.rgba.size(), 0.0f)}, t.mask)
                  .maxError,
              1e-6)
        << "an open plane reflects nothing back onto itself";
}

class SkySuiteTest : public GpuTest {};

// The street under the analytic sky, through the suite's command path (references rendered, not
// cached): the sky's direct term against renders and references with and without the sky, and the
// sun-only case against the suite's sun-only evaluation run on its own.
TEST_F(SkySuiteTest, StreetSkyDirectIsTheDifferenceOfRendersWithAndWithoutTheSky) {
    EvalCliOptions o;
    o.reference.settings.progress = false;
    o.frames = 1;
    const SuiteScene street{"street", "street", "", {}, kWidth, kHeight, kSpp};
    const SuiteRun run = runSuiteCases(o, {street}, ctx());
    ASSERT_EQ(run.sun.size(), 1u);
    ASSERT_EQ(run.sky.size(), 1u);
    ASSERT_EQ(run.sky[0].rows.size(), 2u);

    ReferenceCliOptions ro;
    ro.frame.scene = "street";
    const PreparedFrame f = prepareReferenceFrame(ro);
    const GroundTruth sun = truthOf(f.scene, f.camera, SkySettings{}), both = truthOf(f.scene, f.camera, suiteSky());
    const ImageF refSkyDirect = difference(both.direct, sun.direct);
    RenderSettings base;
    base.width = kWidth, base.height = kHeight;
    const std::vector<EvalVariant> variants = suiteVariants(base);
    // The direct light does not depend on the GI technique: one pair of renders for both rows.
    RenderSettings withSky = variants[0].render;
    withSky.lighting.sky = suiteSky();
    const ImageF skyDirect = difference(renderedDirect(ctx(), f.scene, f.camera, withSky),
                                        renderedDirect(ctx(), f.scene, f.camera, variants[0].render));
    const double byHand = compareImages(skyDirect, refSkyDirect, sun.mask).relL1;
    for (size_t i = 0; i < variants.size(); ++i) {
        std::printf("[ sky ] street %s: sky direct rel L1 %.5f (by hand %.5f), sky bounce %.4f, final %.4f\n",
                    variants[i].technique.c_str(), run.sky[0].rows[i].skyDirect().relL1, byHand,
                    run.sky[0].rows[i].skyBounce().relL1, run.sky[0].rows[i].final().relL1);
        EXPECT_NEAR(run.sky[0].rows[i].skyDirect().relL1, byHand, 1e-3) << variants[i].technique;
    }

    // The sun-only case: the suite's sun-only evaluation, one frame against the seed's reference.
    const GroundTruth second = truthOf(f.scene, f.camera, SkySettings{}, 2);
    const std::vector<EvalRow> rows = runEval(ctx(), f.scene, f.camera, variants, sun, 1, nullptr);
    EXPECT_EQ(run.sun[0].noiseL1, compareImages(second.indirect, sun.indirect, sun.mask).relL1);
    ASSERT_EQ(run.sun[0].rows.size(), rows.size());
    for (size_t i = 0; i < rows.size(); ++i) {
        EXPECT_NEAR(run.sun[0].rows[i].indirect.relL1, rows[i].indirect.relL1, 1e-6) << rows[i].variant.technique;
        EXPECT_NEAR(run.sun[0].rows[i].direct.relL1, rows[i].direct.relL1, 1e-6) << rows[i].variant.technique;
        EXPECT_EQ(run.sun[0].rows[i].variant.render.lighting.sky.kind, SkyKind::Auto) << "no sky: auto unresolved";
    }
}
