// The viewer's GLFW window (no client API: Vulkan draws into it) and what Vulkan needs from the
// window system: instance extensions, a presentation test per queue family, the surface.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/context.h"

struct GLFWwindow;

namespace penumbra::view {

class Window {
public:
    // Throws std::runtime_error("no display (...; use penumbra render)") without a display.
    Window(uint32_t width, uint32_t height, const std::string& title);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    // ContextOptions for a device that presents to this window system.
    vk::ContextOptions presentationOptions(vk::ContextOptions base) const;
    VkSurfaceKHR createSurface(VkInstance instance) const;

    GLFWwindow* handle() const { return window_; }
    bool shouldClose() const;
    void requestClose();
    VkExtent2D drawableSize() const;  // framebuffer pixels; 0x0 while minimised
    // Asks for a drawable size (the window system may take a moment: compare drawableSize()).
    void requestDrawableSize(uint32_t width, uint32_t height);
    void pollEvents();
    void waitEvents();  // blocks until something happens (minimised: no work at all)
    void waitEventsTimeout(double seconds);

    // Files dropped onto the window since the last call.
    std::vector<std::string> takeDroppedFiles();
    // Mouse-wheel steps since the last call (installed before ImGui's, which chains to it).
    double takeScroll();

private:
    GLFWwindow* window_ = nullptr;
    std::vector<std::string> dropped_;
    double scroll_ = 0.0;
};

}  // namespace penumbra::view
