// The sky: radiance from every direction of the world's upper hemisphere (+Y up), its order-2
// spherical harmonics, importance sampling of it and the irradiance it gives. The path tracer samples
// it, the tests integrate it; the renderer uploads maps and uniform skies from it, and evaluates the
// analytic sky on the GPU from its AnalyticSkyModel (src/lighting/gpu_sky.h).
//
// Kinds (`--sky`): none; uniform,r,g,b (radiance (r,g,b) over the upper hemisphere, black below the
// horizon); analytic[,turbidity] (Preetham, Shirley and Smits 1999, driven by the first directional
// light, scaled so that the sun's illuminance equals the light's intensity); FILE.exr (an
// equirectangular map, orientation below).
//
// Equirectangular layout, for maps and for the table every kind is sampled from: row v (0 at the top)
// looks at polar angle theta = pi v from +Y, column u at azimuth phi = 2 pi u - pi, the direction
// (sin(theta) sin(phi), cos(theta), -sin(theta) cos(phi)): the map's centre column looks toward -Z,
// its right quarter toward +X, its left and right edges toward +Z. `rotation` turns a map about +Y by
// that many degrees, counter-clockwise seen from above (the map's -Z column then looks toward -X at
// 90 degrees).
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace penumbra {

enum class SkyKind { Auto, None, Uniform, Analytic, Map };

// What the user asked for. Auto: the commands that show a scene (render, view, bench, reference)
// resolve it at their frame set-up (resolveSkyKind: analytic for a scene with a directional light,
// none otherwise); anything that never resolves it (tests, eval, stability, a program linking the
// library) gets no sky, so that what it measured with the sun alone stays comparable.
struct SkySettings {
    SkyKind kind = SkyKind::Auto;
    glm::vec3 uniformRadiance{1.0f};
    float turbidity = 3.0f;  // analytic: Preetham's atmospheric turbidity, [2, 10]
    std::string mapPath;
    float scale = 1.0f;            // multiplies every kind's radiance
    float rotationDegrees = 0.0f;  // a map's turn about +Y
    // analytic: the sun's illuminance the sky is scaled to (the renderer's units); 0: the first
    // directional light's. The sky keeps its sun when the light's own intensity is 0 (the sky alone).
    float sunIlluminance = 0.0f;
    bool operator==(const SkySettings&) const = default;
};
inline constexpr float kDefaultTurbidity = 3.0f;
inline constexpr float kMinTurbidity = 2.0f, kMaxTurbidity = 10.0f;

// `--sky` text: none | auto | uniform,r,g,b | analytic[,turbidity] | FILE.exr (the file must exist
// and be an OpenEXR file). Throws std::invalid_argument with the reason; skyText is its inverse.
void parseSky(SkySettings& settings, const std::string& text);
std::string skyText(const SkySettings& settings);

// The nine real SH basis functions (Ramamoorthi and Hanrahan 2001) at unit `d`, world axes:
// 0.282095; 0.488603 y, z, x; 1.092548 xy, 1.092548 yz, 0.315392 (3z^2 - 1), 1.092548 xz,
// 0.546274 (x^2 - y^2).
std::array<double, 9> skyShBasis(const glm::dvec3& d);

// The sample points of the equirectangular layout, for code that evaluates a sky on the GPU: row r's
// polar cosine at its texels' centres (the row's mid cosine, where a table is evaluated) and at the
// two Gauss-Legendre points in cos(theta) of the integrals (Sky::sh, Sky::irradiance), with the
// row's span in cos(theta); and the azimuth at `column`, a column index plus the fraction across it.
inline constexpr std::array<double, 2> kSkyGaussOffsets{0.5 - 0.28867513459481287, 0.5 + 0.28867513459481287};
struct SkyRowPoints {
    double cosCentre;
    std::array<double, 2> cosGauss;
    double cosSpan;
};
SkyRowPoints skyRowPoints(uint32_t row, uint32_t height);
double skyAzimuth(double column, uint32_t width);

struct SkySample {
    glm::vec3 direction{0.0f};
    float pdf = 0.0f;  // per unit solid angle
    glm::vec3 radiance{0.0f};
};

// Preetham's clear sky as the handful of numbers it is evaluated from, on the CPU or the GPU: the
// Perez coefficients of luminance Y and chromaticity x, y, their zenith values, the sun and the
// scale to the renderer's radiance.
struct AnalyticSkyModel {
    struct Perez {
        double a, b, c, d, e;
    };
    std::array<Perez, 3> perez{};  // Y, x, y
    glm::dvec3 zenith{0.0};        // Yz (cd/m^2), xz, yz, each over its Perez value at the zenith
    glm::vec3 toSun{0, 1, 0};
    double scale = 1.0;            // cd/m^2 -> renderer radiance
    // `toSun`: unit direction toward the sun; `sunIlluminance`: the sun's luminous irradiance normal
    // to it in the renderer's units (the directional light's intensity times its colour's luminance).
    static AnalyticSkyModel make(float turbidity, const glm::vec3& toSun, float sunIlluminance);
    glm::vec3 radiance(const glm::vec3& direction) const;
};

// A piecewise-constant table over the equirectangular layout.
struct SkyTable {
    uint32_t width = 0, height = 0;
    std::vector<glm::vec3> texels;  // top row first
};

class Sky {
public:
    Sky() = default;  // none
    static Sky uniform(const glm::vec3& radiance);
    // `toSun`: unit direction toward the sun; `sunIlluminance`: the sun's luminous irradiance normal
    // to it in the renderer's units (the directional light's intensity times its colour's luminance).
    static Sky analytic(float turbidity, const glm::vec3& toSun, float sunIlluminance);
    static Sky analytic(const AnalyticSkyModel& model);
    // The analytic sky's table size.
    static constexpr uint32_t kAnalyticWidth = 256, kAnalyticHeight = 128;
    // A map (RGB texels, top row first, the layout above) turned by `rotationDegrees` about +Y.
    static Sky map(SkyTable texels, float rotationDegrees);

    bool enabled() const { return kind_ != SkyKind::None; }
    SkyKind kind() const { return kind_; }
    glm::vec3 radiance(const glm::vec3& direction) const;
    // Radiance in direction d times `factor` (the user's scale).
    void scale(float factor);

    // Order-2 SH of the radiance, integrated over the table's texels in double precision.
    std::array<glm::dvec3, 9> sh() const;
    // A direction by the table's luminance (u in [0,1)^2), and the density of that sampling.
    SkySample sample(const glm::vec2& u) const;
    float pdf(const glm::vec3& direction) const;
    // Irradiance on a surface of unit normal n, unoccluded, over the table in double precision.
    glm::dvec3 irradiance(const glm::vec3& normal) const;
    // The table in the layout above, in the map's own orientation; `rotationRadians` turns it.
    const SkyTable& table() const { return table_; }
    float rotationRadians() const { return rotation_; }
    // Clips texels of the map brighter than a threshold (the sun, which a directional light already
    // gives): returns how many were clipped.
    uint32_t clipSun();

private:
    void buildTable(uint32_t width, uint32_t height);
    void buildDistribution();
    glm::vec3 toMap(const glm::vec3& world) const;
    glm::vec3 toWorld(const glm::vec3& map) const;
    uint32_t texelOf(const glm::vec3& mapDirection) const;

    SkyKind kind_ = SkyKind::None;
    glm::vec3 uniform_{0.0f};
    AnalyticSkyModel analytic_;
    float scale_ = 1.0f;
    float rotation_ = 0.0f;
    SkyTable table_;
    std::vector<double> rowCdf_;     // height + 1
    std::vector<double> columnCdf_;  // height x (width + 1)
    std::vector<double> rowWeight_;  // per row, the row's share
    double totalWeight_ = 0.0;
};

// The sky for the frame's lights (Auto: none; a map read from disk and, with a directional light,
// its sun clipped). Throws std::runtime_error when a map cannot be read. Things the user should know
// (clipping, a sun below the horizon) are appended to `warnings`.
Sky makeSky(const SkySettings& settings, const std::vector<Light>& lights, std::vector<std::string>& warnings);
// The analytic sky of `settings` (kind Analytic) for the frame's lights, the user's scale applied: none
// without a directional light. Its warnings as makeSky's.
std::optional<AnalyticSkyModel> makeAnalyticSky(const SkySettings& settings, const std::vector<Light>& lights,
                                                std::vector<std::string>& warnings);
// The sun's illuminance the analytic sky of `settings` is scaled to: settings.sunIlluminance, or
// without it the first directional light's intensity times its colour's luminance (0 without one).
float skySunIlluminance(const SkySettings& settings, const std::vector<Light>& lights);
// The kind Auto stands for with these lights (other kinds: themselves).
SkyKind resolveSkyKind(const SkySettings& settings, const std::vector<Light>& lights);
// Auto replaced by what it stands for (the commands' frame set-up).
inline void resolveAutoSky(SkySettings& settings, const std::vector<Light>& lights) {
    settings.kind = resolveSkyKind(settings, lights);
}

// Preetham's model in its own units, for the tests to check against: the sun's illuminance normal to
// it through the atmosphere (lux) at zenith angle `sunZenith`.
double preethamSunIlluminance(double turbidity, double sunZenith);

}  // namespace penumbra
