// The LPV gather (shaders/lpv/irradiance.glsl) on the CPU, in double precision: the irradiance a
// receiver takes from a summed light volume read back from the GPU, at a given cascade placement.
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include "shared/types.h"

namespace penumbra::test::lpv_cpu {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kC0 = 0.282094792, kC1 = 0.488602512;

inline glm::dvec4 cosineLobe(const glm::dvec3& n) {
    return {std::sqrt(kPi) / 2.0, -std::sqrt(kPi / 3.0) * n.y, std::sqrt(kPi / 3.0) * n.z, -std::sqrt(kPi / 3.0) * n.x};
}

// Irradiance at x (normal n, towards the light it takes) from the summed volume `accum` (near half,
// then far half) placed as `pc.cascades`, over every cascade, of colour `channel`.
inline double gatherIrradiance(const std::vector<glm::vec4>& accum, const gpu::LpvPush& pc, const glm::dvec3& x,
                               const glm::dvec3& n, int channel = 0) {
    using glm::dvec3;
    const int res = int(pc.resolution);
    const size_t cells = size_t(res) * res * res, half = 3 * pc.cascadeCount * cells;
    auto at = [&](uint32_t k, size_t offset, const dvec3& p) {
        const dvec3 g = (p - dvec3(pc.cascades[k].origin)) / double(pc.cascades[k].cellSize) - 0.5;
        const glm::ivec3 base = glm::ivec3(glm::floor(g));
        const dvec3 f = g - dvec3(base);
        const glm::dvec4 lobe = cosineLobe(-n);
        double e = 0.0;
        for (int i = 0; i < 8; ++i) {
            const glm::ivec3 o(i & 1, (i >> 1) & 1, i >> 2);
            const glm::ivec3 c = glm::clamp(base + o, glm::ivec3(0), glm::ivec3(res - 1));
            const dvec3 w3 = glm::mix(1.0 - f, f, dvec3(o));
            const size_t index = offset + (k * 3 + channel) * cells + (size_t(c.z) * res + c.y) * res + c.x;
            e += w3.x * w3.y * w3.z * glm::dot(glm::dvec4(accum[index]), lobe);
        }
        const double cell = pc.cascades[k].cellSize;
        return std::max(e, 0.0) / (cell * cell);
    };
    double e = 0.0, finer = 0.0;
    for (uint32_t k = 0; k < pc.cascadeCount; ++k) {
        const dvec3 g = (x - dvec3(pc.cascades[k].origin)) / double(pc.cascades[k].cellSize);
        const double inside = std::min({g.x, g.y, g.z, res - g.x, res - g.y, res - g.z});
        const double weight = k + 1 == pc.cascadeCount ? 1.0 : std::clamp((inside - 1.0) / pc.blendCells, 0.0, 1.0);
        const dvec3 p = x + double(pc.cascades[k].cellSize) * n;
        if (weight > 0.0) e += weight * ((k > 0 ? at(k, half, p) : 0.0) + (1.0 - finer) * at(k, 0, p));
        finer = weight;
    }
    return e;
}

}  // namespace penumbra::test::lpv_cpu
