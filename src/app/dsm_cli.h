// The deep-shadow-map and hair options of `penumbra render` (README, "Deep shadow maps") and the
// report printed after rendering. `--shadow dsm` itself is parsed with the shadow options.
#pragma once
#include <CLI/CLI.hpp>

#include "renderer/renderer.h"

namespace penumbra {

void addDsmOptions(CLI::App& cmd, DsmSettings& dsm, BuiltinOptions& scene);

// After parsing (settings.aov set): `--dsm-lights` alone turns deep shadow maps on for those lights;
// the DSM AOVs without deep shadow maps are an error (std::invalid_argument).
void finishDsmSettings(RenderSettings& settings);

// After the last frame: the DSM and camera translucency statistics lines (unless quiet) and the
// overflow warnings, if any.
void reportDsm(Renderer& renderer, bool quiet);

}  // namespace penumbra
