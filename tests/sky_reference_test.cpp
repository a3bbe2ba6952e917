// The path tracer under a sky (core/sky.h): a uniform sky over an open plane gives it irradiance
// pi L (the plane's radiance albedo L), sampled by MIS; camera rays that escape see the sky; a
// single-sided enclosure hides the sky only where its fronts face the sky, in both halves of the MIS.
// CPU only.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "enclosed_plane.h"
#include "reference/path_tracer.h"
#include "scene/builders.h"

namespace penumbra::test {
namespace {

ReferenceSettings skySettings(uint32_t spp, uint32_t bounces, const glm::vec3& radiance) {
    ReferenceSettings s;
    s.width = s.height = 24;
    s.spp = spp, s.bounces = bounces;
    s.threads = 2;
    s.progress = false;
    s.sky.kind = SkyKind::Uniform;
    s.sky.uniformRadiance = radiance;
    return s;
}

TEST(ReferenceSky, UniformSkyOverAnOpenPlaneGivesPiL) {
    Scene scene = makeBuiltinScene("plane");  // albedo 0.5, seen from above
    scene.lights.clear();
    const glm::vec3 l(0.5f, 1.0f, 2.0f);
    for (const uint32_t bounces : {0u, 2u}) {
        const ReferenceImage img = renderReference(scene, scene.cameras[0], skySettings(256, bounces, l));
        glm::dvec3 sum(0.0), variance(0.0);
        for (size_t i = 0; i < img.direct.size(); ++i) {
            ASSERT_TRUE(img.covered[i]);
            sum += glm::dvec3(img.direct[i]);
            variance += glm::dvec3(img.directVar[i]);
            EXPECT_EQ(img.indirect[i], glm::vec3(0.0f)) << "a lone plane has nothing to bounce light from";
        }
        const double n = double(img.direct.size());
        for (int c = 0; c < 3; ++c) {
            const double expected = 0.5 / M_PI * (M_PI * l[c]);  // albedo / pi times the irradiance pi L
            const double standardError = std::sqrt(variance[c]) / n;
            EXPECT_GT(standardError, 0.0);
            EXPECT_NEAR(sum[c] / n, expected, 5.0 * standardError + 1e-6) << "channel " << c;
            EXPECT_NEAR(sum[c] / n, expected, 0.01 * expected) << "channel " << c;
        }
    }
}

// Under a uniform sky of radiance 1 the plane's direct light is albedo / pi x E. Inside a box whose
// fronts face inward (a sky dome) the light's rule lets every sky direction in: E = pi, which needs
// both halves of the MIS (the sky's sample and the scatter ray, which the dome stops by the viewer's
// rule) to see through it. Inside the same box with its fronts facing outward (a closed shed)
// every sky direction leaves through a roof or wall whose front faces the sky: E = 0 in both halves,
// though the scatter ray sees through the box's backs.
TEST(ReferenceSky, ASingleSidedEnclosureHidesTheSkyOnlyWhereItsFrontsFaceTheSky) {
    for (const bool inward : {true, false}) {
        const Scene scene = enclosedPlane(inward);
        const ReferenceImage img = renderReference(scene, scene.cameras[0], skySettings(256, 0, glm::vec3(1.0f)));
        glm::dvec3 sum(0.0), variance(0.0);
        for (size_t i = 0; i < img.direct.size(); ++i) {
            ASSERT_TRUE(img.covered[i]) << "the plane fills the view";
            sum += glm::dvec3(img.direct[i]);
            variance += glm::dvec3(img.directVar[i]);
        }
        const double n = double(img.direct.size()), toIrradiance = M_PI / 0.5;
        for (int c = 0; c < 3; ++c) {
            const double e = sum[c] / n * toIrradiance, standardError = std::sqrt(variance[c]) / n * toIrradiance;
            std::printf("[ sky ] fronts %s: irradiance %.5f, standard error %.5f\n", inward ? "inward" : "outward", e,
                        standardError);
            if (inward) {
                EXPECT_NEAR(e, M_PI, 5.0 * standardError + 1e-6) << "channel " << c;
                EXPECT_NEAR(e, M_PI, 0.01 * M_PI) << "channel " << c;
            } else {
                EXPECT_EQ(e, 0.0) << "channel " << c;
            }
        }
    }
}

TEST(ReferenceSky, EscapingCameraRaysSeeTheSky) {
    Scene scene = makeBuiltinScene("plane");
    scene.lights.clear();
    Camera up = scene.cameras[0];
    up.target = up.eye + glm::vec3(0.0f, 1.0f, 0.0f);
    up.up = glm::vec3(0.0f, 0.0f, -1.0f);
    const glm::vec3 l(0.25f, 0.5f, 1.0f);
    const ReferenceImage img = renderReference(scene, up, skySettings(4, 1, l));
    for (size_t i = 0; i < img.direct.size(); ++i) {
        ASSERT_FALSE(img.covered[i]);
        EXPECT_EQ(img.direct[i], l);
        EXPECT_EQ(img.indirect[i], glm::vec3(0.0f));
    }
    // Without a sky the same rays see black, as before.
    ReferenceSettings none = skySettings(4, 1, l);
    none.sky.kind = SkyKind::None;
    const ReferenceImage black = renderReference(scene, up, none);
    for (const glm::vec3& d : black.direct) EXPECT_EQ(d, glm::vec3(0.0f));
}

}  // namespace
}  // namespace penumbra::test
