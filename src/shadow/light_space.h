// Light-space projections for shadow maps (pure math, unit-tested).
#pragma once
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace penumbra {

struct LightProjection {
    glm::mat4 viewProj{1.0f};
    // World size of one shadow texel: constant for orthographic maps, per unit of distance along
    // the light's axis for perspective maps.
    float texelSize = 0.0f;
    bool perspective = false;
};

// A view matrix looking along `dir` with an up vector that is never parallel to it.
glm::mat4 lookAlong(const glm::vec3& eye, const glm::vec3& dir);

// Orthographic map covering the bounding sphere of `bounds`, looking along the light direction.
LightProjection directionalProjection(const glm::vec3& dir, const Bounds& bounds, uint32_t resolution);

// Perspective map fit to the spot cone (outer angle), near/far fit to the scene bounds.
LightProjection spotProjection(const Light& light, const Bounds& bounds, uint32_t resolution);

// Camera: right-handed view, Vulkan clip space (depth 0..1, y down in NDC so the image is upright).
glm::mat4 cameraViewProj(const Camera& camera, float aspect, float zfar);

}  // namespace penumbra
