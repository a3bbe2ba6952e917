#include "frame/frame_setup.h"

namespace penumbra {

void checkBuiltinSceneBudget(const vk::DeviceLimits& limits, const FrameOptions& frame) {
    if (frame.scene == "hair") checkStrandBudget(limits, frame.builtin.hairStrands);
}

const SceneMotion& frameMotion(const FrameOptions& o, const OptionsDeviceFrame& device) {
    warnIfStill(o, device.motion(), device.frame.scene);
    return device.motion();
}

}  // namespace penumbra
