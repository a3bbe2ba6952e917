// Between the public types of include/penumbra and the renderer's own: the public structs take their
// defaults from the internal ones, so a default is written once, in its technique's folder.
#pragma once
#include "penumbra/penumbra.h"
#include "renderer/render_settings.h"
#include "scene/scene.h"

namespace penumbra::api {

penumbra::RenderSettings toInternal(const Settings& settings);
Settings fromInternal(const penumbra::RenderSettings& settings);
penumbra::Light toInternal(const Light& light);
Light fromInternal(const penumbra::Light& light);
penumbra::Camera toInternal(const Camera& camera);
Camera fromInternal(const penumbra::Camera& camera);
Frame fromInternal(const penumbra::Camera& camera, const std::vector<penumbra::Light>& lights,
                   const std::vector<glm::mat4>& instances);

}  // namespace penumbra::api
