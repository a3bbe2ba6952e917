// The reference path tracer's translucent surfaces (src/reference, docs/evaluation.md):
// hair strands as Embree ribbons of their opacity and BLEND triangles of their alpha, against
// analytic answers: the transmittance through k strands, (1 - a)^k, and through a BLEND quad, 1 - a;
// the expected pixel of a camera ray through them, the over operator front to back (within a few
// Monte-Carlo standard errors); Kajiya-Kay radiance at a known angle; the area-averaged floor
// transmittance under a sheet of strands narrower than their spacing, 1 - a w / s. CPU only.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "reference/path_tracer.h"
#include "reference/ray_scene.h"
#include "scene/builders.h"

using namespace penumbra;

namespace {

constexpr double kPi = 3.14159265358979323846;
// Kajiya-Kay's specular constants (shaders/dsm/kajiya_kay.glsl): strength and cone exponent.
constexpr double kSpecular = 0.08, kExponent = 60.0;

ReferenceSettings settings(uint32_t w, uint32_t h, uint32_t spp, bool antialias = false) {
    ReferenceSettings s;
    s.width = w, s.height = h, s.spp = spp, s.bounces = 0;
    s.threads = 2;
    s.progress = false;
    s.antialias = antialias;
    return s;
}

// The plane scene (albedo 0.5 at y = 0, camera at y = 15 looking down, image x = world x) under a sun
// of irradiance 1 shining along `dir`.
Scene planeUnderSun(const glm::vec3& dir = {0.0f, -1.0f, 0.0f}) {
    Scene s = makeBuiltinScene("plane");
    s.lights[0].direction = glm::normalize(dir);
    s.lights[0].intensity = 1.0f;
    return s;
}

// A straight strand along x at height y, centred on z: one segment (a ray through the joint of two
// would meet both ends).
void addStraightStrand(Scene& s, float y, float z, float width, float opacity, const glm::vec3& colour) {
    Strand style;
    style.width = width, style.opacity = opacity, style.color = colour;
    const glm::vec3 points[] = {{-5.0f, y, z}, {5.0f, y, z}};
    addStrand(s, points, style);
}

// |mean - expected| in standard errors of the pixel's mean (the reference's own variance estimate).
double zScore(const ReferenceImage& img, size_t pixel, int c, double expected) {
    const double se = std::sqrt(double(img.directVar[pixel][c]));
    return std::abs(double(img.direct[pixel][c]) - expected) / std::max(se, 1e-12);
}

}  // namespace

// k strands stacked over the floor, under the sun and the camera (both straight above): the floor's
// shadow AOV is (1 - a)^k exactly (every strand crossed once), and the centre pixel's expected radiance
// is the over operator: sum_i (1 - a)^i a L_i + (1 - a)^k L_floor, strand i lit through the i above it
// with Kajiya-Kay at t.l = t.v = 0 (its specular peak).
TEST(ReferenceHair, StackedStrandsGiveTheOverOperatorAndPowerTransmittance) {
    const double a = 0.3;
    const glm::dvec3 colour(0.4, 0.25, 0.1);
    for (int k : {1, 3, 6}) {
        Scene s = planeUnderSun();
        for (int i = 0; i < k; ++i) addStraightStrand(s, 3.0f - 0.4f * float(i), 0.0f, 1.0f, float(a), colour);
        const uint32_t w = 9, h = 9, centre = 4 * w + 4;  // the centre pixel's ray: straight down at x = z = 0
        const ReferenceImage img = renderReference(s, s.cameras[0], settings(w, h, 4096));
        EXPECT_NEAR(img.shadow[centre], std::pow(1.0 - a, k), 2e-6) << k << " strands";
        const double strandResponse = kSpecular * (kExponent + 2.0) / (2.0 * kPi);  // cone = 1
        for (int c = 0; c < 3; ++c) {
            double expected = 0.0;
            for (int i = 0; i < k; ++i)
                expected += std::pow(1.0 - a, i) * a * std::pow(1.0 - a, i) * (colour[c] / kPi + strandResponse);
            expected += std::pow(1.0 - a, k) * std::pow(1.0 - a, k) * 0.5 / kPi;
            EXPECT_LT(zScore(img, centre, c, expected), 4.5) << k << " strands, channel " << c << ": "
                                                             << img.direct[centre][c] << " vs " << expected;
        }
    }
}

// A BLEND quad of alpha 0.4 over the lit floor: a shadow ray through it keeps 1 - a, and the camera
// sees a x quad + (1 - a) x the floor in its shadow.
TEST(ReferenceHair, BlendQuadTransmitsOneMinusAlpha) {
    const double a = 0.4;
    const glm::dvec3 colour(0.9, 0.2, 0.3);
    Scene s = planeUnderSun();
    const uint32_t glass = addMaterial(s, glm::vec3(colour));
    s.materials[glass].alphaMode = AlphaMode::Blend;
    s.materials[glass].baseColor.a = float(a);
    addQuad(s, {-2, 1, -2}, {0, 0, 4}, {4, 0, 0}, glass);  // facing up: the camera and the light see its front
    const uint32_t w = 9, h = 9, centre = 4 * w + 4;
    const ReferenceImage img = renderReference(s, s.cameras[0], settings(w, h, 4096));
    EXPECT_NEAR(img.shadow[centre], 1.0 - a, 1e-6);
    for (int c = 0; c < 3; ++c) {
        const double expected = a * colour[c] / kPi + (1.0 - a) * (1.0 - a) * 0.5 / kPi;
        EXPECT_LT(zScore(img, centre, c, expected), 4.5) << "channel " << c << ": " << img.direct[centre][c]
                                                         << " vs " << expected;
    }
}

// An opaque strand along x seen from straight above (t.v = 0), lit by a sun 80 degrees from its
// tangent: L = E (albedo / pi + s (n + 2) / (2 pi) sin^n 80) sin 80, no noise.
TEST(ReferenceHair, KajiyaKayRadianceAtAKnownAngle) {
    const double angle = 80.0 * kPi / 180.0;
    const glm::dvec3 colour(0.5, 0.3, 0.2);
    Scene s = planeUnderSun({-float(std::cos(angle)), -float(std::sin(angle)), 0.0f});  // towards the light: (cos, sin, 0)
    addStraightStrand(s, 1.0f, 0.0f, 2.0f, 1.0f, colour);
    const uint32_t w = 9, h = 9, centre = 4 * w + 4;
    const ReferenceImage img = renderReference(s, s.cameras[0], settings(w, h, 1));
    const double sinTL = std::sin(angle);
    for (int c = 0; c < 3; ++c) {
        const double expected =
            (colour[c] / kPi + kSpecular * (kExponent + 2.0) / (2.0 * kPi) * std::pow(sinTL, kExponent)) * sinTL;
        EXPECT_NEAR(img.direct[centre][c], expected, 2e-6 * expected) << "channel " << c;
    }
}

// Strands of width w every s (w / s = 0.2) at height 1, opacity 0.5, sun straight down: a pixel spans
// about 20 spacings, so its area-averaged floor transmittance is 1 - a w / s = 0.9 (anti-aliased
// paths; the camera looks through the strands at the floor for the shadow AOV).
TEST(ReferenceHair, FloorUnderASheetOfStrandsGetsTheCoverageWeightedTransmittance) {
    const float spacing = 0.05f, width = 0.01f, a = 0.5f;
    Scene s = planeUnderSun();
    for (float z = -3.0f; z <= 3.0f; z += spacing) addStraightStrand(s, 1.0f, z, width, a, glm::vec3(0.3f));
    const uint32_t w = 16, h = 16, spp = 512;
    const ReferenceImage img = renderReference(s, s.cameras[0], settings(w, h, spp, true));
    // Pixels whose floor lies well inside the sheet's shadow (|x| < 3.5, |z| < 2): columns and rows 5..10.
    double sum = 0.0;
    int pixels = 0;
    for (uint32_t y = 6; y <= 9; ++y)
        for (uint32_t x = 5; x <= 10; ++x) sum += img.shadow[size_t(y) * w + x], ++pixels;
    const double p = width / spacing, expected = 1.0 - a * p;
    // Each path's transmittance is 1 or 1 - a (a Bernoulli(p) choice): the mean's standard error.
    const double se = a * std::sqrt(p * (1.0 - p) / (double(pixels) * spp));
    EXPECT_NEAR(sum / pixels, expected, 4.5 * se) << "standard error " << se;
}
// Embree drops a curve's hits nearer than two radii to the ray origin; the ray scene starts rays
// behind their origin so that a strand just above a shadow ray's start still counts, and a strand
// just behind it does not. Strands of radius 0.5 every 0.4 above y = 0.2: from y the ray meets
// those above y.
TEST(ReferenceHair, StrandsNextToTheRayOriginCount) {
    Scene s = makeBuiltinScene("plane");
    for (int i = 0; i < 6; ++i) addStraightStrand(s, 0.2f + 0.4f * float(i), 0.0f, 1.0f, 0.3f, glm::vec3(0.5f));
    const reference::RayScene rays(s);
    for (float y : {0.1f, 1.1f, 1.5f, 1.9f, 2.1f}) {
        const int above = int(std::count_if(s.strandPoints.begin(), s.strandPoints.end(),
                                             [&](const glm::vec3& p) { return p.y > y; })) / 2;
        EXPECT_NEAR(rays.transmittance({0.1f, y, 0.1f}, {0.0f, 1.0f, 0.0f}, 100.0f), std::pow(0.7, above), 1e-6)
            << "from y = " << y;
        // A viewer's ray stops at the nearest strand above for some seed: at most 0.2 away.
        float nearest = 1e9f;
        for (uint32_t seed = 0; seed < 64; ++seed)
            if (auto hit = rays.intersect({0.1f, y, 0.1f}, {0.0f, 1.0f, 0.0f}, 0.0f, 100.0f, {seed, -1, false}))
                nearest = std::min(nearest, hit->t);
        if (above > 0) {
            EXPECT_NEAR(nearest, std::fmod(0.2f + 4.0f - y, 0.4f), 1e-5f) << "from y = " << y;
        }
    }
}
