// `penumbra reference`: a CPU path tracer (Embree) over the same Scene, camera and light units as the
// rasterizer, the ground truth that `penumbra compare` and `penumbra eval` measure the techniques
// against. Lambertian surfaces; punctual lights by next-event estimation (a shadow ray per light);
// `bounces` diffuse bounces by cosine-weighted sampling, each bounce's hit lit by next-event
// estimation again. A sky (core/sky.h) lights every vertex by multiple importance sampling (the sky's
// own distribution against the cosine-weighted scatter, power heuristic) and shows where camera rays
// escape; the sky that reaches a camera ray's surface with nothing between is direct light, what is
// reflected on the way is indirect. Radiance meanings match the renderer's AOVs: direct = the light's first
// reflection, indirect = everything after it (one bounce by default, what RSM and LPV approximate),
// final = direct + indirect. Hair strands are Kajiya-Kay-shaded ribbons and, like BLEND surfaces,
// translucent (reference/ray_scene.h): camera and bounce rays stop at them with probability alpha,
// shadow rays collect their transmittance.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/sky.h"
#include "scene/scene.h"

namespace penumbra {

struct ReferenceSettings {
    uint32_t width = 1280;
    uint32_t height = 720;
    uint32_t spp = 64;       // paths per pixel (the bounce; direct light needs one without --aa)
    uint32_t bounces = 1;    // 0 = direct light only
    uint64_t seed = 1;
    uint32_t threads = 0;    // 0 = every hardware thread
    // false: every path starts at the pixel centre, as the rasterizer samples (edges then agree and
    // the comparison measures lighting); true: uniform over the pixel (anti-aliased: what strands
    // far thinner than a pixel need, their coverage of the pixel's area).
    bool antialias = false;
    bool progress = true;    // single-line progress bar on stderr
    // The sky (Auto: none; the `reference` command resolves it as `render` does).
    SkySettings sky;
};

enum class ReferenceAov { Final, Direct, Indirect, Mask, Shadow, Hair };
ReferenceAov parseReferenceAov(const std::string& name);  // final, direct, indirect, mask, shadow, hair

struct ReferenceImage {
    uint32_t width = 0, height = 0, spp = 0;
    std::vector<glm::vec3> direct, indirect;        // mean radiance per pixel, top row first
    std::vector<glm::vec3> directVar, indirectVar;  // variance of that mean (sample variance / n)
    std::vector<uint8_t> covered;                   // 1 where a camera ray of the pixel hit a surface
                                                    // (elsewhere `direct` holds the visible sky)
    // The renderer's shadow AOV: mean visibility of the first shadow-casting light at the opaque
    // surface the camera ray meets behind any translucent layers (transmittance of hair and BLEND
    // surfaces included; 0 where that light does not reach it or nothing is hit).
    std::vector<float> shadow;
    // The fraction of the pixel's camera paths that stop at a hair strand: the hair's alpha in the
    // pixel (coverage x opacity, composited), where anti-aliased.
    std::vector<float> hair;
    double seconds = 0.0;
    uint64_t rays = 0;
    std::vector<std::string> warnings;  // the sky's (a clipped map, a sun below the horizon)

    // RGBA32F of one AOV (mask: 1 on covered pixels), as writeExr takes it.
    std::vector<float> rgba(ReferenceAov aov) const;
    // The image's relative standard error, sqrt(sum var / sum mean^2) over covered pixels (or those
    // `mask` selects) and the three channels (Final: direct and indirect variances added, their
    // covariance neglected).
    double relativeNoise(ReferenceAov aov, const std::vector<uint8_t>& mask = {}) const;
};

// Throws std::invalid_argument for bad settings (size 0, spp 0, bounces > kMaxBounces).
ReferenceImage renderReference(const Scene& scene, const Camera& camera, const ReferenceSettings& settings);
constexpr uint32_t kMaxReferenceBounces = 16;

// Irradiance from `light` at p on a surface facing it (no cosine), KHR_lights_punctual falloff read
// radiometrically (docs/evaluation.md); `toLight` gets the unit direction to the light, `distance` the
// distance to it (infinity for a directional light). Written independently of shaders/core/lights.glsl.
glm::vec3 referenceIrradiance(const Light& light, const glm::vec3& p, glm::vec3& toLight, float& distance);

}  // namespace penumbra
