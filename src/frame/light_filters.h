// Per-light shadow filters (`--light-shadow N=FILTER`), applied to the frame's lights.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "scene/scene.h"

namespace penumbra {

// "N=FILTER" -> (N, filter); throws std::invalid_argument for a malformed spec or an unknown filter.
std::pair<size_t, ShadowFilter> parseLightFilter(const std::string& spec);

// Applies `--light-shadow N=FILTER` to the scene's lights (after `--light` replaced them); throws
// std::invalid_argument for a malformed spec, an unknown filter or a light index out of range.
void applyLightFilters(const std::vector<std::string>& specs, std::vector<Light>& lights);

}  // namespace penumbra
