// The deep-shadow-map report printed after rendering.
#pragma once
#include "renderer/renderer.h"

namespace penumbra {

// After the last frame: the DSM and camera translucency statistics lines (unless quiet) and the
// overflow warnings, if any.
void reportDsm(Renderer& renderer, bool quiet);

}  // namespace penumbra
