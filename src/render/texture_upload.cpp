#include "render/texture_upload.h"

#include <algorithm>

namespace penumbra {
namespace {

constexpr VkFormat kFormat = VK_FORMAT_R8G8B8A8_SRGB;  // blits with linear filtering are mandatory for it
constexpr VkPipelineStageFlags2 kTransfer = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;

// A barrier on levels [first, first + count).
void levelBarrier(VkCommandBuffer cmd, const vk::Image& image, uint32_t first, uint32_t count, VkImageLayout from,
                  VkImageLayout to, VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
    vk::imageBarrier(cmd, image.handle(), {VK_IMAGE_ASPECT_COLOR_BIT, first, count, 0, 1}, from, to, kTransfer,
                     srcAccess, dstStage, dstAccess);
}

int32_t levelSize(uint32_t size, uint32_t level) { return int32_t(std::max(1u, size >> level)); }

// Level l from level l - 1 (level 0 holds the texels, all in TRANSFER_DST); every level ends
// SHADER_READ_ONLY.
void buildMips(VkCommandBuffer c, vk::Image& image) {
    const uint32_t levels = image.mipLevels(), w = image.width(), h = image.height();
    for (uint32_t l = 1; l < levels; ++l) {
        levelBarrier(c, image, l - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_ACCESS_2_TRANSFER_WRITE_BIT, kTransfer, VK_ACCESS_2_TRANSFER_READ_BIT);
        VkImageBlit r{};
        r.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, l - 1, 0, 1};
        r.srcOffsets[1] = {levelSize(w, l - 1), levelSize(h, l - 1), 1};
        r.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, l, 0, 1};
        r.dstOffsets[1] = {levelSize(w, l), levelSize(h, l), 1};
        vkCmdBlitImage(c, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image.handle(),
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &r, VK_FILTER_LINEAR);
    }
    const VkPipelineStageFlags2 shaders = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    if (levels > 1)
        levelBarrier(c, image, 0, levels - 1, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_2_NONE, shaders,
                     VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    levelBarrier(c, image, levels - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                 VK_ACCESS_2_TRANSFER_WRITE_BIT, shaders, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    image.state() = {VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, shaders, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
}

}  // namespace

uint32_t mipLevelCount(uint32_t width, uint32_t height) {
    uint32_t n = 1;
    for (uint32_t s = std::max(width, height); s > 1; s /= 2) ++n;
    return n;
}

uint64_t mipChainBytes(uint32_t width, uint32_t height) {
    uint64_t bytes = 0;
    for (uint32_t l = 0; l < mipLevelCount(width, height); ++l)
        bytes += uint64_t(levelSize(width, l)) * uint64_t(levelSize(height, l)) * 4;
    return bytes;
}

vk::Image uploadTexture(vk::CommandContext& cmd, const Texture& t, const char* name) {
    if (t.width == 0 || t.height == 0 || t.rgba8.size() != size_t(t.width) * t.height * 4)
        throw vk::VulkanError(std::string("texture ") + name + " has no or inconsistent texels");
    vk::Allocator& alloc = cmd.allocator();
    vk::Image image(alloc, {kFormat, t.width, t.height, 1,
                            VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                            name, mipLevelCount(t.width, t.height)});
    vk::Buffer staging(alloc, t.rgba8.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true, "texture-staging");
    staging.write(t.rgba8.data(), t.rgba8.size());
    cmd.submitAndWait([&](VkCommandBuffer c) {
        vk::transitionImage(c, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        copy.imageExtent = {t.width, t.height, 1};
        vkCmdCopyBufferToImage(c, staging.handle(), image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
        buildMips(c, image);
    });
    return image;
}

}  // namespace penumbra
