// The deep-shadow-map module's option table.
#pragma once
#include "core/options.h"
#include "dsm/dsm_settings.h"

namespace penumbra {

const OptionTable& dsmOptions();

}  // namespace penumbra
