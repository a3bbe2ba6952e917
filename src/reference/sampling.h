// Random numbers and the few sampling routines of the reference path tracer. The generator is PCG32
// (O'Neill 2014): small state, so every pixel owns one, seeded from (seed, pixel index); the image
// is then the same whatever the thread count or the order in which tiles finish.
#pragma once
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

namespace penumbra::reference {

// SplitMix64 finaliser: spreads nearby seeds (pixel indices) over the whole 64-bit range.
inline uint64_t mix64(uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

class Pcg32 {
public:
    Pcg32(uint64_t seed, uint64_t stream) : inc_((mix64(stream) << 1) | 1u) {
        next();
        state_ += mix64(seed ^ 0x5DEECE66Dull);
        next();
    }
    uint32_t next() {
        const uint64_t old = state_;
        state_ = old * 6364136223846793005ull + inc_;
        const uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
        const uint32_t rot = uint32_t(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }
    // Uniform in [0, 1): 24 random bits, so that 1.0f is never returned.
    float uniform() { return float(next() >> 8) * 0x1p-24f; }

private:
    uint64_t state_ = 0;
    uint64_t inc_;
};

// Orthonormal basis around a unit vector (Duff et al. 2017, branchless and without a singularity).
inline void basis(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float c = n.x * n.y * a;
    t = {1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x};
    b = {c, sign + n.y * n.y * a, -n.y};
}

// Cosine-weighted direction around unit n (Malley's method): pdf = cos(theta) / pi.
inline glm::vec3 cosineSample(const glm::vec3& n, float u1, float u2) {
    const float r = std::sqrt(u1);
    const float phi = 6.283185307179586f * u2;
    glm::vec3 t, b;
    basis(n, t, b);
    const float z = std::sqrt(std::max(0.0f, 1.0f - u1));
    return glm::normalize(r * std::cos(phi) * t + r * std::sin(phi) * b + z * n);
}

}  // namespace penumbra::reference
