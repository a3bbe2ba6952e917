// `penumbra view`: the window, the swapchain, the render loop (acquire -> renderer frame whose last
// commands blit its tone-mapped image into the swapchain image and draw the UI over it -> present),
// resize / minimise / out-of-date handling, F12 screenshots and the --script driver.
#pragma once
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "view/camera_control.h"
#include "view/panels.h"
#include "view/script.h"
#include "view/session.h"
#include "view/ui_layer.h"
#include "view/window.h"
#include "vk/resources.h"
#include "vk/swapchain.h"

namespace penumbra::view {

struct ViewOptions {
    std::string script;              // --script FILE ("" = interactive)
    std::string present = "fifo";    // --present fifo|mailbox|immediate
    vk::ContextOptions vulkan;
};

class Viewer {
public:
    // `args`: the frame options as given, `parsed` what they parse to (ViewSession); the window takes
    // the frame's size.
    Viewer(const ViewOptions& options, std::vector<FrameArg> args, ParsedFrame parsed);
    ~Viewer();
    void run();  // until the window closes or the script quits; throws on errors

private:
    bool followDrawableSize();
    bool drawFrame();
    void recordPresent(VkCommandBuffer cmd, vk::Image& ldr, uint32_t index);
    void runScript();
    void finishScriptStep();
    void handleInput(double dt);
    void writeUiScreenshot(const std::string& path);
    void f12Screenshot();
    void writePanelsState(const std::string& path);

    Window window_;
    vk::Context ctx_;
    vk::Allocator alloc_;
    vk::Swapchain swapchain_;
    ViewSession session_;
    UiLayer ui_;
    Panels panels_;
    CameraControl control_;
    std::optional<Script> script_;
    ScriptStep step_{ScriptStep::Frames, 0, {}};
    bool stepFrameDone_ = false;
    // Acquisition semaphores: one more than the renderer's frames in flight, so that one is only
    // reused after the frame that waited on it has completed. Render-done ones per swapchain image.
    std::array<VkSemaphore, 3> acquired_{};
    std::vector<VkSemaphore> rendered_;
    uint64_t frame_ = 0;
    VkExtent2D sessionSize_{0, 0};  // the size the options last asked for
    int sizeWaits_ = 0;
    vk::Buffer uiShot_;             // `screenshot-ui`: the swapchain image read back
    bool uiShotPending_ = false;
    VkExtent2D uiShotExtent_{0, 0};
    std::optional<glm::uvec2> imagePixel(double x, double y) const;
    glm::dvec2 cursor_{0.0, 0.0};  // ctrl + left-drag turns the sun
    bool f12Down_ = false;
    int f12Count_ = 0;
    bool f1Down_ = false;
};

}  // namespace penumbra::view
