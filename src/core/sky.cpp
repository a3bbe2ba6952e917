#include "core/sky.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <tuple>
#include <numeric>
#include <stdexcept>

#include <fmt/format.h>

namespace penumbra {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The weight a texel gets in the sampling distribution: the mean of its channels, so that any
// radiance, whatever its colour, has a non-zero density.
double weightOf(const glm::vec3& c) { return std::max(0.0, (double(c.r) + c.g + c.b) / 3.0); }

// Row r's polar-angle cosines at its top and bottom edge.
void rowCosines(uint32_t r, uint32_t height, double& cosTop, double& cosBottom) {
    cosTop = std::cos(kPi * r / height);
    cosBottom = std::cos(kPi * (r + 1) / height);
}

// The direction in the equirectangular layout (sky.h) at polar cosine `cosTheta`, azimuth `phi`.
glm::dvec3 layoutDirection(double cosTheta, double phi) {
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    return {sinTheta * std::sin(phi), cosTheta, -sinTheta * std::cos(phi)};
}

// Calls f(texel index, direction, solid angle) at the Gauss-Legendre points of every texel (two in
// cos(theta) by two in phi, where the solid angle is uniform: exact for the cubics of the SH
// basis' y).
template <class F>
void forEachTexelPoint(const SkyTable& t, F&& f) {
    const double texelPhi = 2.0 * kPi / t.width;
    for (uint32_t r = 0; r < t.height; ++r) {
        const SkyRowPoints row = skyRowPoints(r, t.height);
        const double solidAngle = row.cosSpan / kSkyGaussOffsets.size() * texelPhi / kSkyGaussOffsets.size();
        for (uint32_t c = 0; c < t.width; ++c)
            for (const double cosTheta : row.cosGauss)
                for (const double offset : kSkyGaussOffsets)
                    f(r * t.width + c, layoutDirection(cosTheta, skyAzimuth(c + offset, t.width)), solidAngle);
    }
}

// A map direction turned `rotation` radians about +Y into the world.
glm::vec3 turnToWorld(const glm::vec3& map, float rotation) {
    const float c = std::cos(rotation), s = std::sin(rotation);
    return {c * map.x + s * map.z, map.y, -s * map.x + c * map.z};
}

// The integral of each SH basis function (world axes) over each texel of a table layout turned by
// `rotation`, at forEachTexelPoint's points: a table's projection is then one weighted sum per
// texel. The last layout's weights are kept, since a moving sun makes a new sky every frame.
using ShTexelWeights = std::vector<std::array<double, 9>>;
std::shared_ptr<const ShTexelWeights> shTexelWeights(const SkyTable& layout, float rotation) {
    static std::mutex mutex;
    static std::shared_ptr<const ShTexelWeights> kept;
    static std::tuple<uint32_t, uint32_t, float> keptLayout;
    const std::lock_guard<std::mutex> lock(mutex);
    const auto key = std::make_tuple(layout.width, layout.height, rotation);
    if (kept && keptLayout == key) return kept;
    auto weights = std::make_shared<ShTexelWeights>(size_t(layout.width) * layout.height);
    forEachTexelPoint(layout, [&](uint32_t texel, const glm::dvec3& d, double solidAngle) {
        const std::array<double, 9> y = skyShBasis(glm::dvec3(turnToWorld(glm::vec3(d), rotation)));
        for (int k = 0; k < 9; ++k) (*weights)[texel][k] += y[k] * solidAngle;
    });
    kept = std::move(weights);
    keptLayout = key;
    return kept;
}

}  // namespace

SkyRowPoints skyRowPoints(uint32_t row, uint32_t height) {
    double cosTop, cosBottom;
    rowCosines(row, height, cosTop, cosBottom);
    const double span = cosTop - cosBottom;
    return {0.5 * (cosTop + cosBottom), {cosTop - kSkyGaussOffsets[0] * span, cosTop - kSkyGaussOffsets[1] * span}, span};
}

double skyAzimuth(double column, uint32_t width) { return 2.0 * kPi * column / width - kPi; }

std::array<double, 9> skyShBasis(const glm::dvec3& d) {
    return {0.282095,
            0.488603 * d.y,
            0.488603 * d.z,
            0.488603 * d.x,
            1.092548 * d.x * d.y,
            1.092548 * d.y * d.z,
            0.315392 * (3.0 * d.z * d.z - 1.0),
            1.092548 * d.x * d.z,
            0.546274 * (d.x * d.x - d.y * d.y)};
}

Sky Sky::uniform(const glm::vec3& radiance) {
    Sky s;
    s.kind_ = SkyKind::Uniform;
    s.uniform_ = radiance;
    s.buildTable(32, 16);  // even: the horizon is a row boundary, so the table is exact
    return s;
}

Sky Sky::map(SkyTable texels, float rotationDegrees) {
    if (texels.width == 0 || texels.height == 0 || texels.texels.size() != size_t(texels.width) * texels.height)
        throw std::invalid_argument("sky map: empty or inconsistent table");
    Sky s;
    s.kind_ = SkyKind::Map;
    s.rotation_ = float(double(rotationDegrees) * kPi / 180.0);
    s.table_ = std::move(texels);
    s.buildDistribution();
    return s;
}

// The table at texel centres of the layout (in the map's orientation; uniform and analytic skies
// have no rotation).
void Sky::buildTable(uint32_t width, uint32_t height) {
    table_ = {width, height, std::vector<glm::vec3>(size_t(width) * height)};
    for (uint32_t r = 0; r < height; ++r) {
        const double cosMid = skyRowPoints(r, height).cosCentre;
        for (uint32_t c = 0; c < width; ++c)
            table_.texels[r * width + c] = radiance(toWorld(glm::vec3(layoutDirection(cosMid, skyAzimuth(c + 0.5, width)))));
    }
    buildDistribution();
}

void Sky::buildDistribution() {
    const uint32_t w = table_.width, h = table_.height;
    rowCdf_.assign(h + 1, 0.0);
    columnCdf_.assign(size_t(h) * (w + 1), 0.0);
    const double dPhi = 2.0 * kPi / w;
    for (uint32_t r = 0; r < h; ++r) {
        double cosTop, cosBottom;
        rowCosines(r, h, cosTop, cosBottom);
        const double texelSolidAngle = dPhi * (cosTop - cosBottom);
        double* cdf = &columnCdf_[size_t(r) * (w + 1)];
        for (uint32_t c = 0; c < w; ++c) cdf[c + 1] = cdf[c] + weightOf(table_.texels[r * w + c]) * texelSolidAngle;
        rowCdf_[r + 1] = rowCdf_[r] + cdf[w];
    }
    totalWeight_ = rowCdf_[h];
}

glm::vec3 Sky::toMap(const glm::vec3& world) const {
    const float c = std::cos(rotation_), s = std::sin(rotation_);
    return {c * world.x - s * world.z, world.y, s * world.x + c * world.z};
}

glm::vec3 Sky::toWorld(const glm::vec3& map) const { return turnToWorld(map, rotation_); }

uint32_t Sky::texelOf(const glm::vec3& d) const {
    const double theta = std::acos(std::clamp(double(d.y), -1.0, 1.0));
    const double phi = std::atan2(double(d.x), -double(d.z));
    const uint32_t r = std::min(table_.height - 1, uint32_t(theta / kPi * table_.height));
    const uint32_t c = std::min(table_.width - 1, uint32_t((phi + kPi) / (2.0 * kPi) * table_.width));
    return r * table_.width + c;
}

glm::vec3 Sky::radiance(const glm::vec3& direction) const {
    switch (kind_) {
        case SkyKind::Uniform: return direction.y > 0.0f ? uniform_ : glm::vec3(0.0f);
        case SkyKind::Analytic: return analytic_.radiance(direction);
        case SkyKind::Map: return table_.texels[texelOf(toMap(direction))];
        default: return glm::vec3(0.0f);
    }
}

void Sky::scale(float factor) {
    scale_ *= factor;
    uniform_ *= factor;
    analytic_.scale *= factor;
    for (glm::vec3& t : table_.texels) t *= factor;
    buildDistribution();
}

std::array<glm::dvec3, 9> Sky::sh() const {
    std::array<glm::dvec3, 9> out{};
    if (!enabled()) return out;
    const std::shared_ptr<const ShTexelWeights> weights = shTexelWeights(table_, rotation_);
    for (size_t texel = 0; texel < table_.texels.size(); ++texel) {
        const glm::dvec3 l(table_.texels[texel]);
        for (int k = 0; k < 9; ++k) out[k] += l * (*weights)[texel][k];
    }
    return out;
}

glm::dvec3 Sky::irradiance(const glm::vec3& normal) const {
    glm::dvec3 e(0.0);
    if (!enabled()) return e;
    forEachTexelPoint(table_, [&](uint32_t texel, const glm::dvec3& d, double solidAngle) {
        const double cosine = glm::dot(glm::dvec3(toWorld(glm::vec3(d))), glm::dvec3(normal));
        if (cosine > 0.0) e += glm::dvec3(table_.texels[texel]) * (cosine * solidAngle);
    });
    return e;
}

SkySample Sky::sample(const glm::vec2& u) const {
    if (!enabled() || totalWeight_ <= 0.0) return {};
    const uint32_t w = table_.width, h = table_.height;
    const double ur = double(u.x) * totalWeight_;
    const uint32_t r = uint32_t(std::clamp<ptrdiff_t>(
        std::upper_bound(rowCdf_.begin(), rowCdf_.end(), ur) - rowCdf_.begin() - 1, 0, h - 1));
    const double* cdf = &columnCdf_[size_t(r) * (w + 1)];
    const double rowWeight = cdf[w];
    const double uc = double(u.y) * rowWeight;
    const uint32_t c = uint32_t(std::clamp<ptrdiff_t>(std::upper_bound(cdf, cdf + w + 1, uc) - cdf - 1, 0, w - 1));
    // Within the texel: uniform in solid angle, reusing the leftover of each coordinate.
    const double tr = std::clamp((ur - rowCdf_[r]) / std::max(rowWeight, 1e-300), 0.0, 1.0);
    const double tc = std::clamp((uc - cdf[c]) / std::max(cdf[c + 1] - cdf[c], 1e-300), 0.0, 1.0);
    double cosTop, cosBottom;
    rowCosines(r, h, cosTop, cosBottom);
    const double cosTheta = cosTop + (cosBottom - cosTop) * tr;
    const double phi = 2.0 * kPi * (c + tc) / w - kPi;
    SkySample s;
    s.direction = glm::normalize(toWorld(glm::vec3(layoutDirection(cosTheta, phi))));
    s.radiance = radiance(s.direction);
    s.pdf = pdf(s.direction);
    return s;
}

float Sky::pdf(const glm::vec3& direction) const {
    if (!enabled() || totalWeight_ <= 0.0) return 0.0f;
    const glm::vec3 m = toMap(direction);
    return float(weightOf(table_.texels[texelOf(m)]) / totalWeight_);
}

// The brightest 0.1% of the map's solid angle bounds the rest: a sun disk (a few hundred
// thousandths of the sphere) lies far above it, a sky without a sun loses almost nothing.
uint32_t Sky::clipSun() {
    const uint32_t w = table_.width, h = table_.height;
    std::vector<std::pair<double, double>> byWeight;  // (weight, solid angle)
    byWeight.reserve(table_.texels.size());
    double totalSolidAngle = 0.0;
    for (uint32_t r = 0; r < h; ++r) {
        double cosTop, cosBottom;
        rowCosines(r, h, cosTop, cosBottom);
        const double omega = 2.0 * kPi / w * (cosTop - cosBottom);
        for (uint32_t c = 0; c < w; ++c) byWeight.push_back({weightOf(table_.texels[r * w + c]), omega});
        totalSolidAngle += omega * w;
    }
    std::sort(byWeight.begin(), byWeight.end(), [](auto& a, auto& b) { return a.first > b.first; });
    double covered = 0.0, threshold = 0.0;
    for (const auto& [weight, omega] : byWeight) {
        covered += omega;
        threshold = weight;
        if (covered >= 1e-3 * totalSolidAngle) break;
    }
    uint32_t clipped = 0;
    for (glm::vec3& t : table_.texels)
        if (const double wt = weightOf(t); wt > threshold) {
            t *= float(threshold / wt);
            ++clipped;
        }
    if (clipped) buildDistribution();
    return clipped;
}

SkyKind resolveSkyKind(const SkySettings& settings, const std::vector<Light>& lights) {
    if (settings.kind != SkyKind::Auto) return settings.kind;
    for (const Light& l : lights)
        if (l.type == LightType::Directional) return SkyKind::Analytic;
    return SkyKind::None;
}

}  // namespace penumbra
