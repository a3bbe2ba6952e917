#include "app/frame_setup.h"

namespace penumbra {

void checkBuiltinSceneBudget(const vk::DeviceLimits& limits, const FrameOptions& frame) {
    if (frame.scene == "hair") checkStrandBudget(limits, frame.builtin.hairStrands);
}

}  // namespace penumbra
