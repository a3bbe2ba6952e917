#include "render/texture_upload.h"

#include <algorithm>
#include <string>

namespace penumbra {
namespace {

constexpr VkFormat kFormat = VK_FORMAT_R8G8B8A8_SRGB;  // blits with linear filtering are mandatory for it
constexpr VkPipelineStageFlags2 kTransfer = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;

uint32_t mipCount(uint32_t size) {
    uint32_t n = 1;
    while (size > 1) size /= 2, ++n;
    return n;
}

// A barrier on levels [first, first + count) of every layer.
void levelBarrier(VkCommandBuffer cmd, const vk::Image& image, uint32_t first, uint32_t count, VkImageLayout from,
                  VkImageLayout to, VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
    vk::imageBarrier(cmd, image.handle(), {VK_IMAGE_ASPECT_COLOR_BIT, first, count, 0, image.layers()}, from, to,
                     kTransfer, srcAccess, dstStage, dstAccess);
}

VkImageBlit blitRegion(uint32_t srcW, uint32_t srcH, uint32_t srcLevel, uint32_t srcLayer, uint32_t dstSize,
                       uint32_t dstLevel, uint32_t dstLayer, uint32_t layers) {
    VkImageBlit r{};
    r.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, srcLevel, srcLayer, layers};
    r.srcOffsets[1] = {int32_t(srcW), int32_t(srcH), 1};
    r.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, dstLevel, dstLayer, layers};
    r.dstOffsets[1] = {int32_t(dstSize), int32_t(dstSize), 1};
    return r;
}

// Texture `layer` at its own size into level 0 of its layer (the array is in TRANSFER_DST).
void blitTexture(vk::CommandContext& cmd, vk::Image& array, const Texture& t, uint32_t layer) {
    if (t.width == 0 || t.height == 0 || t.rgba8.size() != size_t(t.width) * t.height * 4)
        throw vk::VulkanError("texture " + std::to_string(layer) + " has no or inconsistent texels");
    vk::Allocator& alloc = cmd.allocator();
    vk::Image source(alloc, {kFormat, t.width, t.height, 1,
                             VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                 VK_IMAGE_USAGE_SAMPLED_BIT,  // every vk::Image has a view
                             "texture-source"});
    vk::Buffer staging(alloc, t.rgba8.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true, "texture-staging");
    staging.write(t.rgba8.data(), t.rgba8.size());
    cmd.submitAndWait([&](VkCommandBuffer c) {
        vk::transitionImage(c, source, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        copy.imageExtent = {t.width, t.height, 1};
        vkCmdCopyBufferToImage(c, staging.handle(), source.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
        vk::transitionImage(c, source, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kTransfer, VK_ACCESS_2_TRANSFER_READ_BIT);
        vk::transitionImage(c, array, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        const VkImageBlit r = blitRegion(t.width, t.height, 0, 0, array.width(), 0, layer, 1);
        vkCmdBlitImage(c, source.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, array.handle(),
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &r, VK_FILTER_LINEAR);
    });
}

// Level l from level l - 1 for every layer at once; every level ends SHADER_READ_ONLY.
void buildMips(vk::CommandContext& cmd, vk::Image& array) {
    const uint32_t levels = array.mipLevels(), layers = array.layers();
    cmd.submitAndWait([&](VkCommandBuffer c) {
        vk::transitionImage(c, array, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        for (uint32_t l = 1, s = array.width(); l < levels; ++l, s /= 2) {
            levelBarrier(c, array, l - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         VK_ACCESS_2_TRANSFER_WRITE_BIT, kTransfer, VK_ACCESS_2_TRANSFER_READ_BIT);
            const VkImageBlit r = blitRegion(s, s, l - 1, 0, std::max(1u, s / 2), l, 0, layers);
            vkCmdBlitImage(c, array.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, array.handle(),
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &r, VK_FILTER_LINEAR);
        }
        const VkPipelineStageFlags2 shaders = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
        if (levels > 1)
            levelBarrier(c, array, 0, levels - 1, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_2_NONE, shaders,
                         VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
        levelBarrier(c, array, levels - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_2_TRANSFER_WRITE_BIT, shaders,
                     VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
        array.state() = {VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, shaders, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
    });
}

}  // namespace

vk::Image uploadTextureArray(vk::CommandContext& cmd, const std::vector<Texture>& textures, uint32_t size) {
    const uint32_t layers = std::max<uint32_t>(1, uint32_t(textures.size()));
    vk::Image array(cmd.allocator(),
                    {kFormat, size, size, layers,
                     VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                     "material-textures", mipCount(size), true});
    cmd.submitAndWait([&](VkCommandBuffer c) {  // white where there is no texture
        vk::transitionImage(c, array, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        const VkClearColorValue white{{1.0f, 1.0f, 1.0f, 1.0f}};
        const VkImageSubresourceRange all = array.fullRange();
        vkCmdClearColorImage(c, array.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &white, 1, &all);
    });
    for (uint32_t i = 0; i < textures.size(); ++i) blitTexture(cmd, array, textures[i], i);
    buildMips(cmd, array);
    return array;
}

}  // namespace penumbra
