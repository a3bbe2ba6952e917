// The temporal-GI module's option table.
#pragma once
#include "core/options.h"
#include "temporal_gi/temporal_gi_settings.h"

namespace penumbra {

const OptionTable& temporalGiOptions();
// Ranges. Throws std::invalid_argument.
void validate(const TemporalGiSettings& settings);

}  // namespace penumbra
