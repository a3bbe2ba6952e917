// Cascaded shadow maps for directional lights (Engel 2006; practical split scheme of Zhang et al. /
// Dimitrov 2007). Pure math, unit-tested (tests/csm_test.cpp).
//
// Stability: a cascade must not change its texel grid while the camera moves or turns, or shadow
// edges crawl ("shimmer"). So (1) each cascade is the bounding sphere of its frustum slice, whose
// radius depends only on the slice depths and the field of view (not on the camera's orientation),
// (2) the light's view basis is fixed in the world, (3) the sphere's centre is snapped to whole
// texels in that basis and (4) the depth range is the scene's, not the slice's. Moving the camera
// then moves each cascade by whole texels only, and the shadow of a world point stays the same.
#pragma once
#include <cstdint>
#include <vector>

#include "core/light_space.h"

namespace penumbra {

struct CascadeSettings {
    uint32_t count = 4;      // 1..8
    float lambda = 0.75f;    // 0 = uniform splits, 1 = logarithmic
    float blend = 0.1f;      // blend band at a cascade's far end, as a fraction of its depth range
    float distance = 0.0f;   // shadowed view depth; 0 = the camera's far plane (quantised, see cascadeFar)
    bool stabilize = true;   // snap to texels (false only to demonstrate shimmering in tests)
};

struct Sphere {
    glm::vec3 center{0.0f};
    float radius = 0.0f;
};

struct Cascade {
    LightProjection projection;
    float splitNear = 0.0f, splitFar = 0.0f;  // view depths the cascade is chosen for
};

// split_i = lambda * n (f/n)^(i/N) + (1 - lambda) (n + (f - n) i/N), i = 0..N: N + 1 view depths.
std::vector<float> cascadeSplits(float znear, float zfar, uint32_t count, float lambda);

// The far end of the cascades for a camera far plane: rounded up to a power of 2^(1/4), so that it
// (and with it every split and cascade size) stays constant while the camera moves a little.
float cascadeFar(float cameraFar);

// Smallest sphere around the part of the camera frustum between view depths n and f.
Sphere frustumSliceSphere(const Camera& camera, float aspect, float n, float f);

// Square orthographic map of sphere `s` looking along `dir`, its half-size enlarged so that
// `marginTexels` texels lie outside the sphere on every side (filter taps near the border), its
// centre snapped to multiples of `snapTexels` texels in the fixed light basis (0: not snapped; the
// margin grows by half a step, so the sphere stays covered), its depth range the scene's.
LightProjection sphereProjection(const glm::vec3& dir, const Sphere& s, const Bounds& scene, uint32_t resolution,
                                 float marginTexels, uint32_t snapTexels);

// All cascades of a directional light for this camera. A slice's sphere larger than the scene's
// bounding sphere is replaced by the latter (fixed, so just as stable, and never wasting texels).
// Slices overlap by the blend band so that both cascades of a band cover it. With `stabilize`, the
// cascades move by multiples of `snapTexels` texels: a map whose texels are resolved or down-sampled
// in blocks (the RSM, LPV's VPLs) keeps its blocks on a world-fixed lattice too.
std::vector<Cascade> fitCascades(const glm::vec3& dir, const Camera& camera, float aspect, float cameraFar,
                                 const Bounds& scene, uint32_t resolution, const CascadeSettings& settings,
                                 float marginTexels, uint32_t snapTexels = 1);

}  // namespace penumbra
