#include "vk/swapchain.h"

#include <algorithm>

#include <fmt/format.h>

namespace penumbra::vk {
namespace {

// Images are written by a blit of already sRGB-encoded values and by a UI drawn in sRGB space:
// a UNORM format with the sRGB colour space shows both as they are (an *_SRGB format would
// encode them twice).
VkSurfaceFormatKHR chooseFormat(VkPhysicalDevice device, VkSurfaceKHR surface) {
    uint32_t n = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &n, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(n);
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &n, formats.data()));
    for (VkFormat want : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM})
        for (const VkSurfaceFormatKHR& f : formats)
            if (f.format == want && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
    throw VulkanError("the display offers no B8G8R8A8_UNORM or R8G8B8A8_UNORM swapchain format");
}

VkPresentModeKHR chooseMode(VkPhysicalDevice device, VkSurfaceKHR surface, VkPresentModeKHR preferred) {
    uint32_t n = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(device, surface, &n, nullptr));
    std::vector<VkPresentModeKHR> modes(n);
    VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(device, surface, &n, modes.data()));
    return std::find(modes.begin(), modes.end(), preferred) != modes.end() ? preferred : VK_PRESENT_MODE_FIFO_KHR;
}

}  // namespace

const char* presentModeName(VkPresentModeKHR mode) {
    switch (mode) {
        case VK_PRESENT_MODE_FIFO_KHR: return "fifo";
        case VK_PRESENT_MODE_MAILBOX_KHR: return "mailbox";
        case VK_PRESENT_MODE_IMMEDIATE_KHR: return "immediate";
        case VK_PRESENT_MODE_FIFO_RELAXED_KHR: return "fifo-relaxed";
        default: return "other";
    }
}

Swapchain::Swapchain(Context& ctx, VkSurfaceKHR surface, VkPresentModeKHR preferred)
    : ctx_(ctx), surface_(surface) {
    VkBool32 supported = VK_FALSE;
    VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(ctx.physicalDevice(), ctx.queueFamily(), surface, &supported));
    if (!supported) {
        vkDestroySurfaceKHR(ctx.instance(), surface, nullptr);
        throw VulkanError(fmt::format("device '{}' cannot present to this window", ctx.info().name));
    }
    const VkSurfaceFormatKHR f = chooseFormat(ctx.physicalDevice(), surface);
    format_ = f.format;
    colorSpace_ = f.colorSpace;
    mode_ = chooseMode(ctx.physicalDevice(), surface, preferred);
}

Swapchain::~Swapchain() {
    if (swapchain_) {
        ctx_.waitIdle();
        destroyViews();
        vkDestroySwapchainKHR(ctx_.device(), swapchain_, nullptr);
    }
    vkDestroySurfaceKHR(ctx_.instance(), surface_, nullptr);
}

void Swapchain::destroyViews() {
    for (VkImageView v : views_) vkDestroyImageView(ctx_.device(), v, nullptr);
    views_.clear();
    images_.clear();
}

bool Swapchain::recreate(VkExtent2D drawable) {
    ctx_.waitIdle();
    VkSurfaceCapabilitiesKHR caps;
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx_.physicalDevice(), surface_, &caps));
    VkExtent2D extent = caps.currentExtent.width != UINT32_MAX ? caps.currentExtent : drawable;
    extent.width = std::clamp(extent.width, caps.minImageExtent.width, caps.maxImageExtent.width);
    extent.height = std::clamp(extent.height, caps.minImageExtent.height, caps.maxImageExtent.height);
    destroyViews();
    VkSwapchainKHR old = swapchain_;
    swapchain_ = VK_NULL_HANDLE;
    if (extent.width == 0 || extent.height == 0 || drawable.width == 0 || drawable.height == 0) {
        if (old) vkDestroySwapchainKHR(ctx_.device(), old, nullptr);
        extent_ = {0, 0};
        return false;
    }
    const VkImageUsageFlags need = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    if ((caps.supportedUsageFlags & need) != need)
        throw VulkanError("the swapchain images cannot be blitted to and drawn into");
    minImageCount_ = std::max(caps.minImageCount, 2u);
    uint32_t count = minImageCount_ + 1;
    if (caps.maxImageCount) count = std::min(count, caps.maxImageCount);

    VkSwapchainCreateInfoKHR ci{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    ci.surface = surface_;
    ci.minImageCount = count;
    ci.imageFormat = format_;
    ci.imageColorSpace = colorSpace_;
    ci.imageExtent = extent;
    ci.imageArrayLayers = 1;
    // TRANSFER_SRC: `screenshot-ui` reads the image back with its UI.
    ci.imageUsage = need | (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    ci.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    ci.preTransform = caps.currentTransform;
    ci.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    if (!(caps.supportedCompositeAlpha & ci.compositeAlpha))
        ci.compositeAlpha = VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha & -caps.supportedCompositeAlpha);
    ci.presentMode = mode_;
    ci.clipped = VK_TRUE;
    ci.oldSwapchain = old;
    VkResult r = vkCreateSwapchainKHR(ctx_.device(), &ci, nullptr, &swapchain_);
    if (old) vkDestroySwapchainKHR(ctx_.device(), old, nullptr);
    VK_CHECK(r);
    extent_ = extent;
    ++generation_;

    uint32_t n = 0;
    VK_CHECK(vkGetSwapchainImagesKHR(ctx_.device(), swapchain_, &n, nullptr));
    images_.resize(n);
    VK_CHECK(vkGetSwapchainImagesKHR(ctx_.device(), swapchain_, &n, images_.data()));
    for (VkImage image : images_) {
        VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        vi.image = image;
        vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
        vi.format = format_;
        vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkImageView view;
        VK_CHECK(vkCreateImageView(ctx_.device(), &vi, nullptr, &view));
        views_.push_back(view);
    }
    return true;
}

std::optional<uint32_t> Swapchain::acquire(VkSemaphore signal, VkFence fence) {
    uint32_t index = 0;
    const VkResult r = vkAcquireNextImageKHR(ctx_.device(), swapchain_, UINT64_MAX, signal, fence, &index);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) return std::nullopt;
    if (r != VK_SUBOPTIMAL_KHR) VK_CHECK(r);
    return index;
}

bool Swapchain::present(uint32_t index, VkSemaphore wait) {
    VkPresentInfoKHR pi{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    pi.waitSemaphoreCount = wait ? 1 : 0;
    pi.pWaitSemaphores = &wait;
    pi.swapchainCount = 1;
    pi.pSwapchains = &swapchain_;
    pi.pImageIndices = &index;
    const VkResult r = vkQueuePresentKHR(ctx_.queue(), &pi);
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) return false;
    VK_CHECK(r);
    return true;
}

}  // namespace penumbra::vk
