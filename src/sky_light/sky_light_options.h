// The sky-light module's option table.
#pragma once
#include "core/options.h"
#include "sky_light/sky_light_settings.h"

namespace penumbra {

const OptionTable& skyLightOptions();
// Ranges. Throws std::invalid_argument.
void validate(const SkyLightSettings& settings);

}  // namespace penumbra
