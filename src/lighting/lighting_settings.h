// Settings of the lighting module (src/lighting): the sky that lights the scene and shows behind it.
#pragma once
#include "core/sky.h"

namespace penumbra {

struct LightingSettings {
    // `--sky`, `--sky-scale`, `--sky-rotation` (core/sky.h). Auto: analytic with a directional light.
    SkySettings sky;
};

}  // namespace penumbra
