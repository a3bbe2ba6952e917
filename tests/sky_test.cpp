// The CPU sky (core/sky.h) against analytic answers: Preetham's formula evaluated again here, the
// uniform hemisphere's SH and irradiance, and Monte Carlo estimates by both samplings.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "core/sky.h"
#include "io/image_io.h"

namespace penumbra::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Preetham, Shirley and Smits 1999, written out again from the paper for the check: the Perez
// function with the turbidity fits of its appendix A.2, zenith luminance and chromaticity, then xyY
// to linear sRGB.
glm::dvec3 preethamRgb(double t, double sunZenith, const glm::dvec3& view, const glm::dvec3& toSun) {
    const double coefficients[3][5] = {
        {0.1787 * t - 1.4630, -0.3554 * t + 0.4275, -0.0227 * t + 5.3251, 0.1206 * t - 2.5771, -0.0670 * t + 0.3703},
        {-0.0193 * t - 0.2592, -0.0665 * t + 0.0008, -0.0004 * t + 0.2125, -0.0641 * t - 0.8989, -0.0033 * t + 0.0452},
        {-0.0167 * t - 0.2608, -0.0950 * t + 0.0092, -0.0079 * t + 0.2102, -0.0441 * t - 1.6537, -0.0109 * t + 0.0529}};
    auto f = [](const double* c, double theta, double gamma) {
        return (1 + c[0] * std::exp(c[1] / std::cos(theta))) *
               (1 + c[2] * std::exp(c[3] * gamma) + c[4] * std::pow(std::cos(gamma), 2));
    };
    const double s = sunZenith;
    const double chi = (4.0 / 9.0 - t / 120.0) * (kPi - 2 * s);
    const double zenith[3] = {
        1000.0 * ((4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192),
        (0.00166 * s * s * s - 0.00375 * s * s + 0.00209 * s) * t * t +
            (-0.02903 * s * s * s + 0.06377 * s * s - 0.03202 * s + 0.00394) * t +
            (0.11693 * s * s * s - 0.21196 * s * s + 0.06052 * s + 0.25886),
        (0.00275 * s * s * s - 0.00610 * s * s + 0.00317 * s) * t * t +
            (-0.04214 * s * s * s + 0.08970 * s * s - 0.04153 * s + 0.00516) * t +
            (0.15346 * s * s * s - 0.26756 * s * s + 0.06670 * s + 0.26688)};
    const double theta = std::acos(view.y), gamma = std::acos(glm::dot(view, toSun));
    double yxy[3];
    for (int k = 0; k < 3; ++k) yxy[k] = zenith[k] * f(coefficients[k], theta, gamma) / f(coefficients[k], 0.0, s);
    const double Y = yxy[0], X = yxy[1] / yxy[2] * Y, Z = (1 - yxy[1] - yxy[2]) / yxy[2] * Y;
    return {3.2404542 * X - 1.5371385 * Y - 0.4985314 * Z, -0.9692660 * X + 1.8760108 * Y + 0.0415560 * Z,
            0.0556434 * X - 0.2040259 * Y + 1.0572252 * Z};
}

glm::dvec3 direction(double theta, double phi) {
    return {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
}

TEST(Sky, AnalyticRadianceIsPreethamsFormula) {
    for (const double turbidity : {2.0, 3.0, 6.0})
        for (const double sunElevation : {15.0, 40.0, 70.0}) {
            const double sunZenith = (90.0 - sunElevation) * kPi / 180.0;
            const glm::dvec3 toSun = direction(sunZenith, 0.3);
            const float sunIlluminance = 3.0f;
            const Sky sky = Sky::analytic(float(turbidity), glm::vec3(toSun), sunIlluminance);
            // The model's units (cd/m^2) to the renderer's: the sun's illuminance becomes the light's.
            const double scale = sunIlluminance / preethamSunIlluminance(turbidity, sunZenith);
            for (double theta = 0.05; theta < 1.5; theta += 0.29)
                for (double phi = 0.0; phi < 6.2; phi += 0.7) {
                    const glm::dvec3 d = direction(theta, phi);
                    const glm::dvec3 expected = preethamRgb(turbidity, sunZenith, d, toSun) * scale;
                    const glm::vec3 got = sky.radiance(glm::vec3(d));
                    for (int c = 0; c < 3; ++c)
                        EXPECT_NEAR(got[c], expected[c], 1e-4 * std::max(1e-3, std::abs(expected[c])))
                            << "T " << turbidity << " elevation " << sunElevation << " theta " << theta << " phi " << phi;
                }
            EXPECT_EQ(sky.radiance(glm::vec3(0.3f, -0.2f, 0.1f)), glm::vec3(0.0f));
        }
}

// The sun through the atmosphere: less at the horizon than overhead, less in a hazier sky, below
// the 128 klux outside it.
TEST(Sky, PreethamSunIsAttenuatedByMassAndTurbidity) {
    const double overhead = preethamSunIlluminance(3.0, 0.0);
    EXPECT_GT(overhead, 60000.0);
    EXPECT_LT(overhead, 128000.0);
    EXPECT_LT(preethamSunIlluminance(3.0, 1.4), overhead);
    EXPECT_LT(preethamSunIlluminance(6.0, 0.0), overhead);
}

// Radiance L on the upper half of a map (its rows above the horizon), black below: the uniform sky.
SkyTable hemisphereMap(uint32_t w, uint32_t h, const glm::vec3& l) {
    SkyTable t{w, h, std::vector<glm::vec3>(size_t(w) * h, glm::vec3(0.0f))};
    for (uint32_t r = 0; r < h / 2; ++r)
        for (uint32_t c = 0; c < w; ++c) t.texels[r * w + c] = l;
    return t;
}

TEST(Sky, ConstantMapIsTheUniformSky) {
    const glm::vec3 l(0.5f, 1.0f, 2.0f);
    const Sky uniform = Sky::uniform(l);
    const Sky map = Sky::map(hemisphereMap(64, 32, l), 37.0f);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 200; ++i) {
        const double cosTheta = 2.0 * u(rng) - 1.0;
        if (std::abs(cosTheta) < 1e-3) continue;  // the horizon itself
        const glm::vec3 d(direction(std::acos(cosTheta), 2.0 * kPi * u(rng)));
        EXPECT_EQ(uniform.radiance(d), map.radiance(d));
        EXPECT_EQ(map.radiance(d), d.y > 0.0f ? l : glm::vec3(0.0f));
    }
    // SH of a uniform hemisphere: 2 pi Y00 L and pi 0.488603 L on Y1-1 (the +Y band), nothing else.
    const auto a = uniform.sh(), b = map.sh();
    for (int k = 0; k < 9; ++k) {
        double expected = 0.0;
        if (k == 0) expected = 2.0 * kPi * 0.282095;
        if (k == 1) expected = kPi * 0.488603;
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(a[k][c], expected * l[c], 1e-4 * l[c]) << "coefficient " << k;
            EXPECT_NEAR(b[k][c], a[k][c], 1e-4 * l[c]) << "coefficient " << k;
        }
    }
}

// The same through `--sky FILE.exr`: a map written to disk and read back, and a directional light's
// sun clipped out of it (one warning; the constant sky has no texel above the rest: none clipped).
TEST(Sky, ConstantExrFileIsTheUniformSky) {
    const glm::vec3 l(0.5f, 1.0f, 2.0f);
    const SkyTable table = hemisphereMap(64, 32, l);
    std::vector<float> rgba;
    for (const glm::vec3& t : table.texels) rgba.insert(rgba.end(), {t.r, t.g, t.b, 1.0f});
    for (int c = 0; c < 3; ++c) rgba[4 * (5 * 64 + 9) + c] = 4000.0f * l[c];  // a one-texel "sun"
    const std::string path = (std::filesystem::temp_directory_path() / "penumbra_sky_test.exr").string();
    writeExr(path, 64, 32, rgba);
    SkySettings settings;
    parseSky(settings, path);
    ASSERT_EQ(settings.kind, SkyKind::Map);
    Light sun;
    sun.type = LightType::Directional;
    std::vector<std::string> warnings;
    const Sky sky = makeSky(settings, {sun}, warnings);
    ASSERT_EQ(warnings.size(), 1u);
    const Sky uniform = Sky::uniform(l);
    const auto a = uniform.sh(), b = sky.sh();
    for (int k = 0; k < 9; ++k)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(b[k][c], a[k][c], 1e-4 * l[c]) << "coefficient " << k;
    warnings.clear();
    const Sky unclipped = makeSky(settings, {}, warnings);  // no directional light: the map as it is
    EXPECT_TRUE(warnings.empty());
    EXPECT_GT(unclipped.sh()[0].r, a[0].r + 1e-3);
    std::filesystem::remove(path);
}

// Irradiance on a plane tilted by alpha under a uniform upper hemisphere: pi L (1 + cos alpha) / 2.
double tiltedIrradiance(double l, double alpha) { return kPi * l * (1.0 + std::cos(alpha)) / 2.0; }

// Monte Carlo irradiance by the sky's importance sampling.
glm::dvec3 sampledIrradiance(const Sky& sky, const glm::vec3& n, int count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    glm::dvec3 sum(0.0);
    for (int i = 0; i < count; ++i) {
        const SkySample s = sky.sample({u(rng), u(rng)});
        EXPECT_NEAR(s.pdf, sky.pdf(s.direction), 1e-4f * s.pdf);
        const double cosine = glm::dot(s.direction, n);
        if (s.pdf > 0.0f && cosine > 0.0) sum += glm::dvec3(s.radiance) * cosine / double(s.pdf);
    }
    return sum / double(count);
}

// Monte Carlo irradiance by directions uniform over the sphere (pdf 1 / 4 pi).
glm::dvec3 uniformlySampledIrradiance(const Sky& sky, const glm::vec3& n, int count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    glm::dvec3 sum(0.0);
    for (int i = 0; i < count; ++i) {
        const glm::vec3 d(direction(std::acos(2.0 * u(rng) - 1.0), 2.0 * kPi * u(rng)));
        const double cosine = glm::dot(d, n);
        if (cosine > 0.0) sum += glm::dvec3(sky.radiance(d)) * cosine * 4.0 * kPi;
    }
    return sum / double(count);
}

TEST(Sky, ImportanceSamplingAgreesWithUniformSampling) {
    const float l = 1.5f;
    const Sky uniform = Sky::uniform(glm::vec3(l));
    const Sky map = Sky::map(hemisphereMap(128, 64, glm::vec3(l)), 90.0f);
    for (const double alpha : {0.0, 1.0, 2.0}) {
        const glm::vec3 n(std::sin(alpha), std::cos(alpha), 0.0f);
        const double expected = tiltedIrradiance(l, alpha);
        for (const Sky* sky : {&uniform, &map}) {
            EXPECT_NEAR(sampledIrradiance(*sky, n, 200000, 3).g, expected, 0.01 * expected) << "alpha " << alpha;
            EXPECT_NEAR(uniformlySampledIrradiance(*sky, n, 200000, 5).g, expected, 0.02 * expected) << "alpha " << alpha;
            EXPECT_NEAR(sky->irradiance(n).g, expected, 0.005 * expected) << "alpha " << alpha;
        }
    }
}

// The analytic sky is far from uniform (bright near the sun): its importance sampling still agrees
// with the table's integral, and a surface facing the sun gets more than one facing away.
TEST(Sky, AnalyticImportanceSamplingMatchesItsIntegral) {
    const glm::vec3 toSun = glm::normalize(glm::vec3(0.6f, 0.5f, 0.2f));
    const Sky sky = Sky::analytic(3.0f, toSun, 5.0f);
    const glm::vec3 up(0, 1, 0);
    const glm::dvec3 integral = sky.irradiance(up);
    const glm::dvec3 sampled = sampledIrradiance(sky, up, 200000, 11);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sampled[c], integral[c], 0.01 * integral[c]);
    EXPECT_GT(sky.irradiance(toSun).g, sky.irradiance(-toSun).g);
    // The sky's SH give the irradiance too (order 2 carries most of a smooth sky's cosine convolution).
    const auto sh = sky.sh();
    const double band[3] = {kPi, 2.0 * kPi / 3.0, kPi / 4.0};
    const std::array<double, 9> y = skyShBasis(glm::dvec3(up));
    double e = 0.0;
    for (int k = 0; k < 9; ++k) e += band[k == 0 ? 0 : (k < 4 ? 1 : 2)] * sh[k].g * y[k];
    EXPECT_NEAR(e, integral.g, 0.05 * integral.g);
}

TEST(Sky, SettingsParseAndRefuse) {
    SkySettings s;
    parseSky(s, "uniform,1,2,3");
    EXPECT_EQ(s.kind, SkyKind::Uniform);
    EXPECT_EQ(s.uniformRadiance, glm::vec3(1, 2, 3));
    EXPECT_EQ(skyText(s), "uniform,1,2,3");
    parseSky(s, "analytic");
    EXPECT_EQ(s.turbidity, kDefaultTurbidity);
    parseSky(s, "analytic,5.5");
    EXPECT_EQ(s.turbidity, 5.5f);
    parseSky(s, "none");
    EXPECT_EQ(s.kind, SkyKind::None);
    for (const char* bad : {"uniform,1,1", "uniform,1,-1,1", "analytic,50", "analytic,x", "sky", "missing.exr", ""})
        EXPECT_THROW(parseSky(s, bad), std::invalid_argument) << bad;
}

// Auto: analytic with a directional light, none without; a command's frame set-up resolves it.
TEST(Sky, AutoFollowsTheLights) {
    SkySettings s;
    Light point;
    point.type = LightType::Point;
    Light sun;
    sun.type = LightType::Directional;
    EXPECT_EQ(resolveSkyKind(s, {point}), SkyKind::None);
    EXPECT_EQ(resolveSkyKind(s, {point, sun}), SkyKind::Analytic);
    std::vector<std::string> warnings;
    EXPECT_FALSE(makeSky(s, {sun}, warnings).enabled());  // unresolved: no sky
    resolveAutoSky(s, {sun});
    EXPECT_TRUE(makeSky(s, {sun}, warnings).enabled());
}

}  // namespace
}  // namespace penumbra::test
