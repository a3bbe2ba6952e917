#include "shadow/cascades.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace penumbra {

std::vector<float> cascadeSplits(float znear, float zfar, uint32_t count, float lambda) {
    std::vector<float> splits(count + 1);
    for (uint32_t i = 0; i <= count; ++i) {
        const float t = float(i) / float(count);
        const float logSplit = znear * std::pow(zfar / znear, t);
        const float uniformSplit = znear + (zfar - znear) * t;
        splits[i] = lambda * logSplit + (1.0f - lambda) * uniformSplit;
    }
    splits.front() = znear;  // exact ends, whatever the rounding of pow
    splits.back() = zfar;
    return splits;
}

float cascadeFar(float cameraFar) {
    return std::exp2(std::ceil(4.0f * std::log2(std::max(cameraFar, 1e-3f))) / 4.0f);
}

Sphere frustumSliceSphere(const Camera& camera, float aspect, float n, float f) {
    // In view space the slice's corners are (+-z tx, +-z ty, z) for z = n, f; with k^2 = tx^2 + ty^2
    // the sphere centred on the axis at depth c is equidistant from both rings when
    // c = (n + f)(1 + k^2) / 2; past f the far ring alone decides (c = f, radius f k).
    const float ty = std::tan(0.5f * camera.fovy), tx = ty * aspect;
    const float k2 = tx * tx + ty * ty;
    const float c = std::min(0.5f * (n + f) * (1.0f + k2), f);
    const float radius = std::sqrt((f - c) * (f - c) + f * f * k2);
    const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
    return {camera.eye + forward * c, radius};
}

LightProjection sphereProjection(const glm::vec3& dir, const Sphere& s, const Bounds& scene, uint32_t resolution,
                                 float marginTexels, uint32_t snapTexels) {
    const float res = float(resolution);
    // Snapping moves the centre by up to half a step: blocks of several texels get that much more
    // margin (a one-texel snap keeps the margin as it always was: half a texel of it may go).
    const float margin = marginTexels + (snapTexels > 1 ? 0.5f * float(snapTexels) : 0.0f);
    const float half = s.radius * res / std::max(res - 2.0f * margin, 1.0f);
    const float texel = 2.0f * half / res;
    // Fixed basis: the view matrix from the world origin, so texel lattices of all frames coincide.
    const glm::mat4 view = lookAlong(glm::vec3(0.0f), dir);
    glm::vec2 c = glm::vec2(view * glm::vec4(s.center, 1.0f));
    if (snapTexels > 0) {
        const float step = texel * float(snapTexels);
        c = glm::round(c / step) * step;
    }
    // Depth: every scene point, so that casters outside the sphere but towards the light still cast.
    float zmin = 1e30f, zmax = -1e30f;
    for (int i = 0; i < 8; ++i) {
        glm::vec3 corner{(i & 1) ? scene.max.x : scene.min.x, (i & 2) ? scene.max.y : scene.min.y,
                         (i & 4) ? scene.max.z : scene.min.z};
        const float depth = -(view * glm::vec4(corner, 1.0f)).z;
        zmin = std::min(zmin, depth);
        zmax = std::max(zmax, depth);
    }
    const float pad = 0.01f * std::max(zmax - zmin, 1e-3f);
    zmin -= pad;
    zmax += pad;
    const glm::mat4 proj = glm::ortho(c.x - half, c.x + half, c.y - half, c.y + half, zmin, zmax);
    return {proj * view, texel, false, false, zmin, zmax};
}

std::vector<Cascade> fitCascades(const glm::vec3& dir, const Camera& camera, float aspect, float cameraFar,
                                 const Bounds& scene, uint32_t resolution, const CascadeSettings& settings,
                                 float marginTexels, uint32_t snapTexels) {
    const float znear = std::max(camera.znear, 1e-3f);
    const float zfar = std::max(settings.distance > 0.0f ? settings.distance : cascadeFar(cameraFar), 2.0f * znear);
    const std::vector<float> splits = cascadeSplits(znear, zfar, settings.count, settings.lambda);
    const Sphere sceneSphere{scene.center(), std::max(scene.radius(), 1e-3f)};
    std::vector<Cascade> cascades;
    for (uint32_t i = 0; i < settings.count; ++i) {
        // Cascade i also serves the blend band at the far end of cascade i - 1.
        const float bandStart = i == 0 ? splits[0] : splits[i] - settings.blend * (splits[i] - splits[i - 1]);
        Sphere s = frustumSliceSphere(camera, aspect, bandStart, splits[i + 1]);
        if (s.radius >= sceneSphere.radius) s = sceneSphere;
        cascades.push_back({sphereProjection(dir, s, scene, resolution, marginTexels, settings.stabilize ? snapTexels : 0u), splits[i],
                            splits[i + 1]});
    }
    return cascades;
}

}  // namespace penumbra
