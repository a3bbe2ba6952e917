// Overlays drawn with ImGui's background draw list over the rendered image: the shadow layers'
// frusta (cascade bounds, spot cones, cube faces) and the LPV cascades' boxes, as projected lines.
#pragma once
#include "renderer/renderer.h"

namespace penumbra::view {

struct OverlayOptions {
    bool shadowFrusta = false;
    bool lpvBoxes = false;
};

// Draws over an image of `width` x `height` pixels seen through `camera`.
void drawOverlays(const OverlayOptions& options, Renderer& renderer, const Camera& camera, uint32_t width,
                  uint32_t height);

}  // namespace penumbra::view
