// The shadow options of `penumbra render` (README, "CLI"): filter per light and for all lights,
// filter parameters, cascades, point-light maps.
#pragma once
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "dsm/dsm_settings.h"
#include "shadow/shadow_settings.h"

namespace penumbra {

// Adds the options to `cmd`; `lightFilters` collects the repeatable `--light-shadow N=MODE`;
// `deep` is enabled by `--shadow dsm` or `dom` (alone or with a filter: `--shadow pcf,dsm`).
void addShadowOptions(CLI::App& cmd, ShadowSettings& settings, std::vector<std::string>& lightFilters,
                      DsmSettings& deep);

// Applies `--light-shadow N=MODE` to the scene's lights (after `--light` replaced them); throws
// std::invalid_argument for a malformed spec, an unknown mode or a light index out of range.
void applyLightFilters(const std::vector<std::string>& specs, std::vector<Light>& lights);

}  // namespace penumbra
