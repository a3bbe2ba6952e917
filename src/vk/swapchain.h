// A VkSwapchainKHR over a surface: format and present-mode choice, (re)creation for a drawable
// size, acquire and present with out-of-date / suboptimal reported to the caller. Knows no window
// library (the caller creates the surface) and nothing about what is drawn.
#pragma once
#include <optional>
#include <vector>

#include "vk/context.h"

namespace penumbra::vk {

class Swapchain {
public:
    // Takes ownership of `surface`. `preferred` falls back to FIFO (always supported) when the
    // surface lacks it.
    Swapchain(Context& ctx, VkSurfaceKHR surface, VkPresentModeKHR preferred);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    // (Re)creates the images for the drawable size (the surface's own extent where it has one).
    // Returns false and keeps no images when the extent is 0 (a minimised window). Waits for the
    // device first: the old images may still be in use.
    bool recreate(VkExtent2D drawable);

    // The next image, its acquisition signalling `signal` and/or `fence`; nullopt when the
    // swapchain is out of date (recreate, then try again). Suboptimal images are returned and
    // reported by present().
    std::optional<uint32_t> acquire(VkSemaphore signal, VkFence fence = VK_NULL_HANDLE);
    // Queues image `index` for presentation after `wait` (may be null); false when the swapchain
    // is out of date or suboptimal and should be recreated.
    bool present(uint32_t index, VkSemaphore wait);

    bool valid() const { return swapchain_ != VK_NULL_HANDLE; }
    VkFormat format() const { return format_; }
    VkExtent2D extent() const { return extent_; }
    VkPresentModeKHR presentMode() const { return mode_; }
    uint32_t imageCount() const { return uint32_t(images_.size()); }
    uint32_t minImageCount() const { return minImageCount_; }
    VkImage image(uint32_t i) const { return images_.at(i); }
    VkImageView view(uint32_t i) const { return views_.at(i); }
    // Incremented by every recreate(): framebuffers over the views compare it to rebuild.
    uint32_t generation() const { return generation_; }

private:
    void destroyViews();

    Context& ctx_;
    VkSurfaceKHR surface_;
    VkPresentModeKHR mode_ = VK_PRESENT_MODE_FIFO_KHR;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkColorSpaceKHR colorSpace_ = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
    VkExtent2D extent_{0, 0};
    uint32_t minImageCount_ = 2;
    uint32_t generation_ = 0;
    std::vector<VkImage> images_;
    std::vector<VkImageView> views_;
};

const char* presentModeName(VkPresentModeKHR mode);

}  // namespace penumbra::vk
