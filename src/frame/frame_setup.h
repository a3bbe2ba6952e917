// A frame's device and scene from its options: DeviceFrame (renderer/device_frame.h) with its steps
// taken from FrameOptions, each step once.
#pragma once
#include <optional>

#include "frame/frame_options.h"
#include "renderer/device_frame.h"

namespace penumbra {

// The built-in scene's size options (`--strands` of `hair`) before the scene is built.
void checkBuiltinSceneBudget(const vk::DeviceLimits& limits, const FrameOptions& frame);

class FrameOptionsSource : public FrameSource {
public:
    explicit FrameOptionsSource(const FrameOptions& o) : options_(o) {}
    void checkSettings(RenderSettings& settings) const override { checkFrameSettings(options_, settings); }
    void checkScene(const vk::DeviceLimits& limits) const override { checkBuiltinSceneBudget(limits, options_); }
    PreparedFrame load(RenderSettings&) const override { return loadFrame(options_); }
    void loaded(const PreparedFrame& frame) const override { motion_.emplace(checkedMotion(options_, frame)); }
    // The motion over the loaded frame (after DeviceFrame built it).
    const SceneMotion& motion() const { return *motion_; }

private:
    const FrameOptions& options_;
    mutable std::optional<SceneMotion> motion_;
};

namespace detail {
// Constructed before the DeviceFrame base, so that the source outlives the construction and keeps
// what it built over the frame.
struct WithFrameOptionsSource {
    FrameOptionsSource source;
};
}  // namespace detail

// What `render`, `bench` and `stability` do before their work.
struct OptionsDeviceFrame : private detail::WithFrameOptionsSource, DeviceFrame {
    OptionsDeviceFrame(const FrameOptions& o, RenderSettings& settings, const vk::ContextOptions& vkOptions)
        : WithFrameOptionsSource{FrameOptionsSource(o)}, DeviceFrame(source, settings, vkOptions) {}
    const SceneMotion& motion() const { return source.motion(); }
};

// What moves in the device's frame, built once as it was loaded; warns as frameMotion does.
const SceneMotion& frameMotion(const FrameOptions& o, const OptionsDeviceFrame& device);

}  // namespace penumbra
