// Settings of the lighting module (src/lighting): the sky that lights the scene and shows behind it,
// and what the auto exposure meters.
#pragma once
#include "core/sky.h"

namespace penumbra {

struct LightingSettings {
    // `--sky`, `--sky-scale`, `--sky-rotation` (core/sky.h). Auto: analytic with a directional light.
    SkySettings sky;
    // `--exposure-percentiles LOW,HIGH`: `--exposure auto` meters the geometry pixels ranked between
    // these percentiles of luminance (lighting/auto_exposure.h); 0,100 is the plain log-average.
    // 50,98: the brighter half meters, so hard shadows (black without GI, up to half a view) drop out.
    float exposureLowPercentile = 50.0f, exposureHighPercentile = 98.0f;
};

}  // namespace penumbra
