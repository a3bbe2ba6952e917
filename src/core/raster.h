// Dynamic-rendering set-up shared by the raster passes: every target cleared, viewport and scissor
// covering the whole extent.
#pragma once
#include <vector>

#include <vulkan/vulkan.h>

namespace penumbra {

struct ColorTarget {
    VkImageView view;
    VkClearColorValue clear;
};

struct RasterTarget {
    VkExtent2D extent;
    std::vector<ColorTarget> colors;
    VkImageView depth = VK_NULL_HANDLE;  // cleared to 1 (far)
    bool load = false;  // keep the targets' contents instead of clearing (a second pass drawing into them)
};

// vkCmdBeginRendering with clears (or loads) + viewport/scissor; end with vkCmdEndRendering.
void beginRaster(VkCommandBuffer cmd, const RasterTarget& target);

}  // namespace penumbra
