// The RSM module's option table and the checks of its settings.
#pragma once
#include "core/options.h"
#include "rsm/rsm_settings.h"

namespace penumbra {

const OptionTable& rsmOptions();
// Ranges and combinations of the RSM's own settings (the CLI's rows check each value as it is parsed;
// this holds settings built in code to the same rules). Throws std::invalid_argument.
void validate(const RsmSettings& settings);

}  // namespace penumbra
