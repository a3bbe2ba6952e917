#include "core/light_space.h"

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
    return {proj * view, 2.0f * r / float(resolution), false, false, 0.5f * r, 3.5f * r};
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
    return {proj * view, 2.0f * std::tan(halfAngle) / float(resolution), true, false, znear, zfar * 1.01f};
}

glm::vec2 pointLightRange(const Light& light, const Bounds& bounds) {
    float zfar = 1e-3f;
    for (int i = 0; i < 8; ++i) {
        glm::vec3 corner{(i & 1) ? bounds.max.x : bounds.min.x, (i & 2) ? bounds.max.y : bounds.min.y,
                         (i & 4) ? bounds.max.z : bounds.min.z};
        zfar = std::max(zfar, glm::length(corner - light.position));
    }
    if (light.range > 0.0f) zfar = std::min(zfar, light.range);
    zfar *= 1.01f;
    return {std::max(zfar * 1e-3f, 1e-3f), zfar};
}

std::array<LightProjection, 6> cubeFaceProjections(const glm::vec3& position, glm::vec2 range, uint32_t resolution,
                                                   float marginTexels) {
    static const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const float res = float(resolution);
    const float tanHalf = res / std::max(res - 2.0f * marginTexels, 1.0f);  // 45 degrees at the margin
    const glm::mat4 proj = glm::perspective(2.0f * std::atan(tanHalf), 1.0f, range.x, range.y);
    std::array<LightProjection, 6> faces;
    for (int f = 0; f < 6; ++f)
        faces[f] = {proj * lookAlong(position, axes[f]), 2.0f * tanHalf / res, true, false, range.x, range.y};
    return faces;
}

float paraboloidDiscScale(uint32_t resolution, float marginTexels) {
    return std::max(1.0f - 2.0f * marginTexels / float(resolution), 0.5f);
}

std::array<LightProjection, 2> paraboloidProjections(const glm::vec3& position, const glm::vec3& axis, glm::vec2 range,
                                                     uint32_t resolution, float marginTexels) {
    // On the axis r' = tan(theta / 2) changes by 1/2 per radian: a texel (2 / (res k) in r') spans
    // 4 / (res k) radians there, i.e. that much world size per unit distance (less towards the rim).
    const float k = paraboloidDiscScale(resolution, marginTexels);
    const float texel = 4.0f / (float(resolution) * k);
    const glm::vec3 a = glm::normalize(axis);
    return {LightProjection{lookAlong(position, a), texel, false, true, range.x, range.y, k},
            LightProjection{lookAlong(position, -a), texel, false, true, range.x, range.y, k}};
}

glm::vec3 paraboloidMap(const LightProjection& h, const glm::vec3& world) {
    const glm::vec3 v = glm::vec3(h.viewProj * glm::vec4(world, 1.0f));
    const float d = glm::length(v);
    const float forward = -v.z;
    const glm::vec2 xy = h.discScale * glm::vec2(v) / std::max(d + forward, 1e-6f * d);
    return {xy, (d - h.zNear) / (h.zFar - h.zNear)};
}

glm::mat4 cameraViewProj(const Camera& camera, float aspect, float zfar) {
    glm::mat4 view = glm::lookAt(camera.eye, camera.target, camera.up);
    glm::mat4 proj = glm::perspective(camera.fovy, aspect, camera.znear, zfar);
    proj[1][1] *= -1.0f;  // Vulkan NDC has y down
    return proj * view;
}

}  // namespace penumbra
