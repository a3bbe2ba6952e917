// The lighting module's option table: the sky. The path tracer's command reads the same rows.
#pragma once
#include "core/options.h"
#include "lighting/lighting_settings.h"

namespace penumbra {

const OptionTable& lightingOptions();
// Ranges. Throws std::invalid_argument.
void validate(const LightingSettings& settings);

}  // namespace penumbra
