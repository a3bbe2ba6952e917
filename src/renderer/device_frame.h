// Device creation and scene loading, in the order every front end follows before its work: the
// settings' own rules, the device, the scene's size options against the device (before a built-in
// scene is grown), the scene and camera, then every resource against the device. The command line
// (src/app) and the viewer supply the steps as a FrameSource; this module knows no option syntax.
#pragma once
#include "renderer/device_budget.h"
#include "renderer/render_settings.h"
#include "scene/scene.h"
#include "vk/context.h"

namespace penumbra {

// A frame's scene, with the lights it is rendered under, and its camera.
struct PreparedFrame {
    Scene scene;
    Camera camera;
};

// Where a frame comes from. Each step throws std::invalid_argument (or SceneError) with one line.
class FrameSource {
public:
    virtual ~FrameSource() = default;
    // The settings' combinations and derived values, before the device is opened.
    virtual void checkSettings(RenderSettings&) const {}
    // Size options of what load() will build, against the device, before it is built.
    virtual void checkScene(const vk::DeviceLimits&) const {}
    // The scene (lights applied) and the camera.
    virtual PreparedFrame load(RenderSettings& settings) const = 0;
    // The loaded frame in its final place (DeviceFrame::frame), before its resources are estimated:
    // what refers to it (the scene's motion) is built here once, its checks before the budget's.
    virtual void loaded(const PreparedFrame&) const {}
};

struct DeviceFrame {
    vk::Context ctx;
    PreparedFrame frame;
    DeviceFrame(const FrameSource& source, RenderSettings& settings, const vk::ContextOptions& vkOptions);
    // Throws when the validation layer reported anything (`--validate`).
    void checkValidation() const;
};

}  // namespace penumbra
