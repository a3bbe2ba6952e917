// Light-space projections for shadow maps (pure math, unit-tested).
#pragma once
#include <array>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace penumbra {

struct LightProjection {
    // World -> clip. Paraboloid layers: world -> the hemisphere's view space only (the paraboloid
    // mapping is not linear; the vertex stage and the lookup apply it, see paraboloidProjections).
    glm::mat4 viewProj{1.0f};
    // World size of one shadow texel: constant for orthographic maps, per unit of distance along
    // the light's axis for perspective maps (paraboloid: per unit distance, on the axis).
    float texelSize = 0.0f;
    bool perspective = false;
    bool paraboloid = false;
    float zNear = 0.0f, zFar = 1.0f;  // view distances of depth 0 and 1 (to linearise stored depth)
    float discScale = 1.0f;           // paraboloid: ndc radius of the 90-degree rim (paraboloidDiscScale)
};

// A view matrix looking along `dir` with an up vector that is never parallel to it.
glm::mat4 lookAlong(const glm::vec3& eye, const glm::vec3& dir);

// Orthographic map covering the bounding sphere of `bounds`, looking along the light direction.
LightProjection directionalProjection(const glm::vec3& dir, const Bounds& bounds, uint32_t resolution);

// Perspective map fit to the spot cone (outer angle), near/far fit to the scene bounds.
LightProjection spotProjection(const Light& light, const Bounds& bounds, uint32_t resolution);

// Point lights: near/far distances that enclose the scene (clamped to the light's range).
glm::vec2 pointLightRange(const Light& light, const Bounds& bounds);

// Six 90-degree perspective faces, in the order +x, -x, +y, -y, +z, -z (the lookup picks the face of
// the major axis). The field of view is widened so that `marginTexels` texels on every side lie
// beyond 45 degrees: filter taps and bilinear footprints at a face's border still read real depth.
std::array<LightProjection, 6> cubeFaceProjections(const glm::vec3& position, glm::vec2 range, uint32_t resolution,
                                                   float marginTexels);

// Dual-paraboloid (Brabec et al. 2002): hemisphere h looks along (h == 0 ? axis : -axis). A direction
// v (view space, forward = -z) at distance d maps to ndc.xy = k * v.xy / (d + forward), depth
// (d - near) / (far - near). k = paraboloidDiscScale shrinks the 90-degree circle by `marginTexels`
// so that each hemisphere also holds a rim beyond 90 degrees for filtering across the seam.
std::array<LightProjection, 2> paraboloidProjections(const glm::vec3& position, const glm::vec3& axis, glm::vec2 range,
                                                     uint32_t resolution, float marginTexels);
float paraboloidDiscScale(uint32_t resolution, float marginTexels);
// The mapping itself (tests and CPU checks; the shaders implement the same): xy = ndc, z = depth.
glm::vec3 paraboloidMap(const LightProjection& hemisphere, const glm::vec3& world);

// Camera: right-handed view, Vulkan clip space (depth 0..1, y down in NDC so the image is upright).
glm::mat4 cameraViewProj(const Camera& camera, float aspect, float zfar);

}  // namespace penumbra
