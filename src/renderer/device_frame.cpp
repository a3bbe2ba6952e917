#include "renderer/device_frame.h"

#include <stdexcept>

#include <fmt/format.h>

namespace penumbra {
namespace {

// The settings' own rules come before the device is opened.
const vk::ContextOptions& afterSettingsCheck(const FrameSource& source, RenderSettings& settings,
                                             const vk::ContextOptions& vkOptions) {
    source.checkSettings(settings);
    return vkOptions;
}

}  // namespace

DeviceFrame::DeviceFrame(const FrameSource& source, RenderSettings& settings, const vk::ContextOptions& vkOptions)
    : ctx(afterSettingsCheck(source, settings, vkOptions)) {
    source.checkScene(ctx.limits());
    frame = source.load(settings);
    source.loaded(frame);
    checkDeviceBudget(ctx, settings, frame.scene);
}

void DeviceFrame::checkValidation() const {
    if (ctx.validationMessages() > 0)
        throw std::runtime_error(fmt::format("{} validation message(s) reported", ctx.validationMessages()));
}

}  // namespace penumbra
