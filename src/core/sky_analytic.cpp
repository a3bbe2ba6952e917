// The analytic clear sky of Preetham, Shirley and Smits, "A Practical Analytic Model for Daylight"
// (SIGGRAPH 1999): the Perez distribution of luminance Y and chromaticity x, y with the paper's
// turbidity fits (its appendix A.2), the zenith values of its appendix, and its sun: the
// extraterrestrial sun attenuated by Rayleigh scattering and aerosols along the relative optical mass
// (its appendix A.1), which gives the model's own ratio of sky to sun for the sun's elevation.
#include <algorithm>
#include <cmath>

#include "core/sky.h"

namespace penumbra {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The sun's illuminance outside the atmosphere, normal to it (lux).
constexpr double kExtraterrestrialIlluminance = 128000.0;

double perezValue(double a, double b, double c, double d, double e, double cosTheta, double gamma) {
    return (1.0 + a * std::exp(b / cosTheta)) * (1.0 + c * std::exp(d * gamma) + e * std::cos(gamma) * std::cos(gamma));
}

// Photopic luminous efficiency V(lambda), a Gaussian fit (lambda in micrometres).
double photopic(double lambda) { return 1.019 * std::exp(-285.4 * (lambda - 0.559) * (lambda - 0.559)); }

// Spectral shape of the extraterrestrial sun: a black body at 5778 K (lambda in micrometres).
double solarSpectrum(double lambda) {
    const double c2 = 14387.77;  // second radiation constant, micrometre kelvin
    return 1.0 / (std::pow(lambda, 5.0) * (std::exp(c2 / (lambda * 5778.0)) - 1.0));
}

// CIE XYZ to linear sRGB (Rec. 709 primaries, D65).
glm::dvec3 xyzToRgb(const glm::dvec3& xyz) {
    return {3.2404542 * xyz.x - 1.5371385 * xyz.y - 0.4985314 * xyz.z,
            -0.9692660 * xyz.x + 1.8760108 * xyz.y + 0.0415560 * xyz.z,
            0.0556434 * xyz.x - 0.2040259 * xyz.y + 1.0572252 * xyz.z};
}

// The sun's zenith angle the model takes: at most 85 degrees. Nearer the horizon the sun's own light
// falls towards 0 through the air mass while the fitted sky does not, so the sky scaled to the sun's
// irradiance would grow without bound; a lower sun keeps the sky of a sun 5 degrees high.
double modelSunZenith(const glm::vec3& toSun) {
    constexpr double kLowestElevation = 5.0 * kPi / 180.0;
    return std::acos(std::clamp(double(toSun.y), std::sin(kLowestElevation), 1.0));
}

}  // namespace

double preethamSunIlluminance(double turbidity, double sunZenith) {
    const double zenithDegrees = sunZenith * 180.0 / kPi;
    const double opticalMass = 1.0 / (std::cos(sunZenith) + 0.15 * std::pow(93.885 - zenithDegrees, -1.253));
    const double beta = 0.04608 * turbidity - 0.04586;  // Angstrom's turbidity coefficient
    constexpr double alpha = 1.3;                       // wavelength exponent of the aerosols
    double transmitted = 0.0, outside = 0.0;
    for (double lambda = 0.380; lambda <= 0.7801; lambda += 0.005) {
        const double rayleigh = std::exp(-0.008735 * std::pow(lambda, -4.08) * opticalMass);
        const double aerosol = std::exp(-beta * std::pow(lambda, -alpha) * opticalMass);
        const double weight = photopic(lambda) * solarSpectrum(lambda);
        transmitted += weight * rayleigh * aerosol;
        outside += weight;
    }
    return kExtraterrestrialIlluminance * transmitted / outside;
}

AnalyticSkyModel AnalyticSkyModel::make(float turbidity, const glm::vec3& toSun, float sunIlluminance) {
    AnalyticSkyModel m;
    m.toSun = glm::normalize(toSun);
    const double t = turbidity;
    const double theta = modelSunZenith(m.toSun);
    m.perez[0] = {0.1787 * t - 1.4630, -0.3554 * t + 0.4275, -0.0227 * t + 5.3251, 0.1206 * t - 2.5771,
                  -0.0670 * t + 0.3703};
    m.perez[1] = {-0.0193 * t - 0.2592, -0.0665 * t + 0.0008, -0.0004 * t + 0.2125, -0.0641 * t - 0.8989,
                  -0.0033 * t + 0.0452};
    m.perez[2] = {-0.0167 * t - 0.2608, -0.0950 * t + 0.0092, -0.0079 * t + 0.2102, -0.0441 * t - 1.6537,
                  -0.0109 * t + 0.0529};
    const double chi = (4.0 / 9.0 - t / 120.0) * (kPi - 2.0 * theta);
    const double zenithLuminance = ((4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192) * 1000.0;
    const double th2 = theta * theta, th3 = th2 * theta;
    const double xz = t * t * (0.00166 * th3 - 0.00375 * th2 + 0.00209 * theta) +
                      t * (-0.02903 * th3 + 0.06377 * th2 - 0.03202 * theta + 0.00394) +
                      (0.11693 * th3 - 0.21196 * th2 + 0.06052 * theta + 0.25886);
    const double yz = t * t * (0.00275 * th3 - 0.00610 * th2 + 0.00317 * theta) +
                      t * (-0.04214 * th3 + 0.08970 * th2 - 0.04153 * theta + 0.00516) +
                      (0.15346 * th3 - 0.26756 * th2 + 0.06670 * theta + 0.26688);
    m.zenith = {zenithLuminance, xz, yz};
    for (int k = 0; k < 3; ++k) {  // the Perez value at the zenith, once, not at every direction
        const Perez& p = m.perez[k];
        m.zenith[k] /= perezValue(p.a, p.b, p.c, p.d, p.e, 1.0, theta);
    }
    m.scale = double(sunIlluminance) / preethamSunIlluminance(t, theta);
    return m;
}

// Y, x, y by the Perez distribution relative to the zenith, then XYZ, then linear sRGB in the
// renderer's units. The view's cosine is kept above a small floor, where the fits' exponential
// term meets the horizon. (shaders/sky/analytic.comp evaluates the same in single precision.)
glm::vec3 AnalyticSkyModel::radiance(const glm::vec3& direction) const {
    const glm::dvec3 d = glm::normalize(glm::dvec3(direction));
    if (d.y <= 0.0) return glm::vec3(0.0f);
    const double cosTheta = std::max(d.y, 1e-3);
    const double gamma = std::acos(std::clamp(glm::dot(d, glm::dvec3(toSun)), -1.0, 1.0));
    glm::dvec3 yxy;
    for (int k = 0; k < 3; ++k) {
        const Perez& p = perez[k];
        yxy[k] = zenith[k] * perezValue(p.a, p.b, p.c, p.d, p.e, cosTheta, gamma);
    }
    const double luminance = yxy[0], x = yxy[1], y = yxy[2];
    const glm::dvec3 xyz{x * luminance / y, luminance, (1.0 - x - y) * luminance / y};
    return glm::vec3(glm::max(xyzToRgb(xyz), glm::dvec3(0.0)) * scale);
}

Sky Sky::analytic(float turbidity, const glm::vec3& toSun, float sunIlluminance) {
    return analytic(AnalyticSkyModel::make(turbidity, toSun, sunIlluminance));
}

Sky Sky::analytic(const AnalyticSkyModel& model) {
    Sky s;
    s.kind_ = SkyKind::Analytic;
    s.analytic_ = model;
    s.buildTable(kAnalyticWidth, kAnalyticHeight);
    return s;
}

}  // namespace penumbra
