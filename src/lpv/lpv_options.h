// The LPV module's option table.
#pragma once
#include "core/options.h"
#include "lpv/lpv_settings.h"

namespace penumbra {

const OptionTable& lpvOptions();
// Ranges and the module's own combinations (the VPL grid divides the RSM). Throws std::invalid_argument.
void validate(const LpvSettings& settings);

}  // namespace penumbra
