#include "view/window.h"

#include <stdexcept>
#include <utility>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <fmt/format.h>

namespace penumbra::view {
namespace {

std::string glfwErrorText() {
    const char* text = nullptr;
    glfwGetError(&text);
    return text ? text : "unknown GLFW error";
}

}  // namespace

Window::Window(uint32_t width, uint32_t height, const std::string& title) {
    if (!glfwInit())
        throw std::runtime_error(fmt::format("no display ({}; use penumbra render)", glfwErrorText()));
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw std::runtime_error("no display with Vulkan presentation (GLFW found no Vulkan loader; use penumbra render)");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_FALSE);  // --width/--height are drawable pixels
    window_ = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
    if (!window_) {
        const std::string error = glfwErrorText();
        glfwTerminate();
        throw std::runtime_error(fmt::format("no display (cannot open a window: {}; use penumbra render)", error));
    }
    glfwSetWindowUserPointer(window_, this);
    glfwSetDropCallback(window_, [](GLFWwindow* w, int count, const char** paths) {
        auto* self = static_cast<Window*>(glfwGetWindowUserPointer(w));
        for (int i = 0; i < count; ++i) self->dropped_.push_back(paths[i]);
    });
    glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double dy) {
        static_cast<Window*>(glfwGetWindowUserPointer(w))->scroll_ += dy;
    });
}

Window::~Window() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

vk::ContextOptions Window::presentationOptions(vk::ContextOptions base) const {
    uint32_t n = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&n);
    if (!names) throw std::runtime_error(fmt::format("no Vulkan surface support: {}", glfwErrorText()));
    for (uint32_t i = 0; i < n; ++i) base.instanceExtensions.push_back(names[i]);
    base.presentSupport = [](VkInstance instance, VkPhysicalDevice device, uint32_t family) {
        return glfwGetPhysicalDevicePresentationSupport(instance, device, family) == GLFW_TRUE;
    };
    return base;
}

VkSurfaceKHR Window::createSurface(VkInstance instance) const {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    const VkResult r = glfwCreateWindowSurface(instance, window_, nullptr, &surface);
    if (r != VK_SUCCESS) throw vk::VulkanError(fmt::format("cannot create a window surface: {}", glfwErrorText()));
    return surface;
}

bool Window::shouldClose() const { return glfwWindowShouldClose(window_); }
void Window::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

VkExtent2D Window::drawableSize() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return {uint32_t(w), uint32_t(h)};
}

void Window::requestDrawableSize(uint32_t width, uint32_t height) {
    glfwSetWindowSize(window_, int(width), int(height));
}

void Window::pollEvents() { glfwPollEvents(); }
void Window::waitEvents() { glfwWaitEvents(); }
void Window::waitEventsTimeout(double seconds) { glfwWaitEventsTimeout(seconds); }

std::vector<std::string> Window::takeDroppedFiles() { return std::exchange(dropped_, {}); }
double Window::takeScroll() { return std::exchange(scroll_, 0.0); }

}  // namespace penumbra::view
