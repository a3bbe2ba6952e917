// Where a pixel's surface point was in the previous frame (core/motion.glsl): the inputs every
// pass using it declares, shared by the velocity AOV (lighting) and the GI history (temporal_gi).
#pragma once
#include "core/frame_graph.h"

namespace penumbra {

// The inputs of core/motion.glsl at bindings first..first + 2: "gbuffer.ids", "drawn-triangles",
// "instances".
void declarePreviousFrameInputs(PassBuilder& pass, uint32_t first, VkSampler nearest);

}  // namespace penumbra
