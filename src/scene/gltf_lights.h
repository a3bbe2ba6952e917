// KHR_lights_punctual lights and perspective cameras of a glTF file (internal to the glTF loader).
// Values the glTF specification forbids (negative or non-finite colours and intensities, cone angles
// outside (0, pi/2], a yfov outside (0, pi), znear above zfar) and lights strong enough to overflow
// the lighting (kMaxLightStrength) are clamped or replaced, each with one warning.
#pragma once
#include <functional>
#include <optional>
#include <string>

#include <tiny_gltf.h>

#include "scene/light_limits.h"
#include "scene/scene.h"

namespace penumbra::gltf {

using Warn = std::function<void(const std::string&)>;

// Light `index` of the file as a node named `nodeName` uses it (position and direction are left to the
// caller); nullopt for an unknown type (warned: dropped).
std::optional<Light> readLight(const tinygltf::Model& model, int index, const std::string& nodeName, const Warn& warn);

// Camera `index`'s projection (its pose is the caller's); nullopt for a non-perspective camera (warned).
std::optional<Camera> readCamera(const tinygltf::Model& model, int index, const Warn& warn);

}  // namespace penumbra::gltf
