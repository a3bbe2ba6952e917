#include "shadow/light_space.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace penumbra {

glm::mat4 lookAlong(const glm::vec3& eye, const glm::vec3& dir) {
    glm::vec3 d = glm::normalize(dir);
    glm::vec3 up = std::abs(d.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    return glm::lookAt(eye, eye + d, up);
}

LightProjection directionalProjection(const glm::vec3& dir, const Bounds& bounds, uint32_t resolution) {
    const glm::vec3 c = bounds.center();
    const float r = std::max(bounds.radius(), 1e-3f);
    // Eye outside the sphere; the sphere spans depths [r, 3r] from it.
    glm::mat4 view = lookAlong(c - glm::normalize(dir) * (2.0f * r), dir);
    glm::mat4 proj = glm::ortho(-r, r, -r, r, 0.5f * r, 3.5f * r);
    return {proj * view, 2.0f * r / float(resolution), false};
}

LightProjection spotProjection(const Light& light, const Bounds& bounds, uint32_t resolution) {
    const glm::vec3 d = glm::normalize(light.direction);
    // Farthest and nearest scene depth along the axis (bounds corners), clamped to the light range.
    float zfar = 1e-3f;
    for (int i = 0; i < 8; ++i) {
        glm::vec3 corner{(i & 1) ? bounds.max.x : bounds.min.x, (i & 2) ? bounds.max.y : bounds.min.y,
                         (i & 4) ? bounds.max.z : bounds.min.z};
        zfar = std::max(zfar, glm::dot(corner - light.position, d));
    }
    if (light.range > 0.0f) zfar = std::min(zfar, light.range);
    const float znear = std::max(zfar * 1e-3f, 1e-3f);
    const float halfAngle = std::min(light.outerConeAngle, 1.5f);  // keep the frustum finite
    const float fovy = 2.0f * halfAngle;
    glm::mat4 proj = glm::perspective(fovy, 1.0f, znear, zfar * 1.01f);
    glm::mat4 view = lookAlong(light.position, d);
    return {proj * view, 2.0f * std::tan(halfAngle) / float(resolution), true};
}

glm::mat4 cameraViewProj(const Camera& camera, float aspect, float zfar) {
    glm::mat4 view = glm::lookAt(camera.eye, camera.target, camera.up);
    glm::mat4 proj = glm::perspective(camera.fovy, aspect, camera.znear, zfar);
    proj[1][1] *= -1.0f;  // Vulkan NDC has y down
    return proj * view;
}

}  // namespace penumbra
