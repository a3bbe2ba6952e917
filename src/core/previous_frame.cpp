#include "core/previous_frame.h"

#include "core/names.h"

namespace penumbra {

void declarePreviousFrameInputs(PassBuilder& pass, uint32_t first, VkSampler nearest) {
    FrameGraph& g = pass.graph();
    pass.sampled(first, g.image(names::kGbufferIds), nearest)
        .storageBuffer(first + 1, g.buffer(names::kDrawnTriangles))
        .storageBuffer(first + 2, g.buffer(names::kInstances));
}

}  // namespace penumbra
