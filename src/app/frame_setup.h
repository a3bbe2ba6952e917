// The command line's frame set-up: DeviceFrame (renderer/device_frame.h) with its steps taken from
// the parsed frame options.
#pragma once
#include "app/frame_options.h"
#include "renderer/device_frame.h"

namespace penumbra {

// The built-in scene's size options (`--strands` of `hair`) before the scene is built.
void checkBuiltinSceneBudget(const vk::DeviceLimits& limits, const FrameOptions& frame);

class CliFrameSource : public FrameSource {
public:
    explicit CliFrameSource(const FrameOptions& o) : options_(o) {}
    void checkSettings(RenderSettings& settings) const override { checkFrameSettings(options_, settings); }
    void checkScene(const vk::DeviceLimits& limits) const override { checkBuiltinSceneBudget(limits, options_); }
    PreparedFrame load(RenderSettings& settings) const override { return prepareFrame(options_, settings); }

private:
    const FrameOptions& options_;
};

// What `render`, `bench` and `stability` do before their work.
struct CliDeviceFrame : DeviceFrame {
    CliDeviceFrame(const FrameOptions& o, RenderSettings& settings, const vk::ContextOptions& vkOptions)
        : DeviceFrame(CliFrameSource(o), settings, vkOptions) {}
};

}  // namespace penumbra
