// The shadow-map module's option table and the checks of its settings.
#pragma once
#include "core/options.h"
#include "shadow/shadow_settings.h"

namespace penumbra {

const OptionTable& shadowOptions();

}  // namespace penumbra
