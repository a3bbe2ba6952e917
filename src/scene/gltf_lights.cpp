#include "scene/gltf_lights.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <glm/gtc/constants.hpp>

namespace penumbra::gltf {
namespace {

// Colour components in [0, kMaxLightStrength] (non-finite ones become 0), then the intensity in
// [0, kMaxLightStrength / the largest component]; one warning for each change.
void clampStrength(Light& l, double intensity, const std::string& what, const Warn& warn) {
    const glm::vec3 given = l.color;
    for (int c = 0; c < 3; ++c)
        l.color[c] = std::isfinite(l.color[c]) ? std::clamp(l.color[c], 0.0f, kMaxLightStrength) : 0.0f;
    if (l.color != given)
        warn(fmt::format("{}: colour ({}, {}, {}) clamped to [0, {}]", what, given.x, given.y, given.z,
                         kMaxLightStrength));
    if (!(intensity >= 0.0) || !std::isfinite(intensity)) {
        warn(fmt::format("{}: intensity {} clamped to 0", what, intensity));
        intensity = 0.0;
    }
    const float brightest = std::max({l.color.x, l.color.y, l.color.z});
    const double largest = brightest > 0.0f ? double(kMaxLightStrength) / brightest : double(kMaxLightStrength);
    if (intensity > largest) {
        warn(fmt::format("{}: intensity {} clamped to {:.6g}: intensity x colour must be at most {} (the largest "
                         "value of the RGBA16F lighting targets)", what, intensity, largest, kMaxLightStrength));
        intensity = largest;
    }
    l.intensity = float(intensity);
}

// glTF: 0 < outer <= pi/2 and 0 <= inner < outer. An outer angle of 0 or less takes the specification's
// default (pi/4), one above pi/2 is clamped to pi/2; the inner angle is clamped below the outer one.
void clampCone(Light& l, const tinygltf::SpotLight& spot, const std::string& what, const Warn& warn) {
    const double outer = spot.outerConeAngle, inner = spot.innerConeAngle;
    l.outerConeAngle = float(outer);
    if (!(outer > 0.0) || !std::isfinite(outer)) {
        l.outerConeAngle = glm::quarter_pi<float>();
        warn(fmt::format("{}: spot outer angle {} is not in (0, pi/2]: the default pi/4 is used", what, outer));
    } else if (outer > glm::half_pi<double>()) {
        l.outerConeAngle = glm::half_pi<float>();
        warn(fmt::format("{}: spot outer angle {} clamped to pi/2 (glTF: at most pi/2)", what, outer));
    }
    l.innerConeAngle = float(inner);
    if (!(inner >= 0.0) || !(float(inner) < l.outerConeAngle)) {
        l.innerConeAngle = std::isfinite(inner) && inner > 0.0 ? l.outerConeAngle * 0.999f : 0.0f;
        warn(fmt::format("{}: spot inner angle {} clamped to {:.6g} (glTF: 0 <= inner < outer {:.6g})", what, inner,
                         l.innerConeAngle, l.outerConeAngle));
    }
}

}  // namespace

std::optional<Light> readLight(const tinygltf::Model& model, int index, const std::string& nodeName, const Warn& warn) {
    const tinygltf::Light& gl = model.lights[size_t(index)];
    Light l;
    l.name = gl.name.empty() ? nodeName : gl.name;
    const std::string what = fmt::format("light {} '{}'", index, l.name);
    if (gl.type == "directional") l.type = LightType::Directional;
    else if (gl.type == "spot") l.type = LightType::Spot;
    else if (gl.type == "point") l.type = LightType::Point;
    else {
        warn(fmt::format("{}: unknown type '{}' (KHR_lights_punctual: directional, spot, point): dropped", what,
                         gl.type));
        return std::nullopt;
    }
    if (gl.color.size() == 3) l.color = glm::vec3(gl.color[0], gl.color[1], gl.color[2]);
    clampStrength(l, gl.intensity, what, warn);
    if (gl.range < 0.0 || !std::isfinite(gl.range))
        warn(fmt::format("{}: range {} is not positive: the light reaches everywhere", what, gl.range));
    l.range = gl.range > 0.0 && std::isfinite(gl.range) ? float(gl.range) : 0.0f;
    if (l.type == LightType::Spot) clampCone(l, gl.spot, what, warn);
    return l;
}

std::optional<Camera> readCamera(const tinygltf::Model& model, int index, const Warn& warn) {
    const tinygltf::Camera& gc = model.cameras[size_t(index)];
    const std::string what = fmt::format("camera {}{}", index, gc.name.empty() ? "" : " '" + gc.name + "'");
    if (gc.type != "perspective") {  // Camera is perspective only; --camera-index counts the ones kept
        warn(fmt::format("{} is {}: skipped (only perspective cameras are supported; the camera index counts the "
                         "perspective ones)", what, gc.type));
        return std::nullopt;
    }
    Camera cam;
    const auto& pc = gc.perspective;
    if (pc.yfov > 0.0 && pc.yfov < glm::pi<double>()) cam.fovy = float(pc.yfov);
    else warn(fmt::format("{}: yfov {} is not in (0, pi): {:.6g} is used", what, pc.yfov, cam.fovy));
    if (pc.znear > 0.0 && std::isfinite(pc.znear)) cam.znear = float(pc.znear);
    else warn(fmt::format("{}: znear {} is not positive: {} is used", what, pc.znear, cam.znear));
    // zfar 0 (absent) is glTF's infinite projection: the far plane comes from the scene bounds.
    if (pc.zfar > cam.znear && std::isfinite(pc.zfar)) cam.zfar = float(pc.zfar);
    else if (pc.zfar != 0.0)
        warn(fmt::format("{}: zfar {} is not beyond znear {}: the far plane comes from the scene bounds", what,
                         pc.zfar, cam.znear));
    return cam;
}

}  // namespace penumbra::gltf
