// What the public handles of include/penumbra/penumbra.h hold.
#pragma once
#include <memory>

#include "penumbra/penumbra.h"
#include "scene/scene.h"
#include "vk/context.h"

namespace penumbra::api {

struct SceneData::Impl {
    penumbra::Scene scene;
};

struct Device::Impl {
    std::unique_ptr<vk::Context> ctx;
};

}  // namespace penumbra::api
