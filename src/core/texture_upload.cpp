#include "core/texture_upload.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "vk/format_bytes.h"

namespace penumbra {
namespace {

constexpr VkFormat kFormat = VK_FORMAT_R8G8B8A8_SRGB;  // blits with linear filtering are mandatory for it
constexpr VkPipelineStageFlags2 kTransfer = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;

// A barrier on levels [first, first + count) of every layer.
void levelBarrier(VkCommandBuffer cmd, const vk::Image& image, uint32_t first, uint32_t count, VkImageLayout from,
                  VkImageLayout to, VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
    vk::imageBarrier(cmd, image.handle(), {VK_IMAGE_ASPECT_COLOR_BIT, first, count, 0, image.layers()}, from, to,
                     kTransfer, srcAccess, dstStage, dstAccess);
}

int32_t levelSize(uint32_t size, uint32_t level) { return int32_t(std::max(1u, size >> level)); }

// Level l from level l - 1 in every layer (level 0 holds the texels, all in TRANSFER_DST); every
// level ends SHADER_READ_ONLY.
void buildMips(VkCommandBuffer c, vk::Image& image) {
    const uint32_t levels = image.mipLevels(), w = image.width(), h = image.height();
    for (uint32_t l = 1; l < levels; ++l) {
        levelBarrier(c, image, l - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_ACCESS_2_TRANSFER_WRITE_BIT, kTransfer, VK_ACCESS_2_TRANSFER_READ_BIT);
        VkImageBlit r{};
        r.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, l - 1, 0, image.layers()};
        r.srcOffsets[1] = {levelSize(w, l - 1), levelSize(h, l - 1), 1};
        r.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, l, 0, image.layers()};
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
        bytes += uint64_t(levelSize(width, l)) * uint64_t(levelSize(height, l)) * vk::texelBytes(kFormat);
    return bytes;
}

uint64_t TextureTablePlan::bytes() const {
    uint64_t total = 0;
    for (const TextureSlot& slot : slots) total += mipChainBytes(slot.width, slot.height) * slot.textures.size();
    return total;
}

std::string TextureTablePlan::warning() const {
    if (resampled == 0) return {};
    const TextureSlot& shared = slots.back();
    return fmt::format("{} textures are resampled to {}x{}: the material texture table holds {} image sizes and "
                       "the scene has more",
                       resampled, shared.width, shared.height, MATERIAL_TEXTURE_SLOTS);
}

TextureTablePlan planTextureTable(const std::vector<Texture>& textures, uint32_t slots, uint32_t maxLayers) {
    // Same-size groups in order of first use, split at maxLayers.
    std::vector<TextureSlot> groups;
    std::map<std::pair<uint32_t, uint32_t>, size_t> open;  // size -> its group still filling
    for (uint32_t i = 0; i < textures.size(); ++i) {
        const auto size = std::make_pair(textures[i].width, textures[i].height);
        auto it = open.find(size);
        if (it == open.end() || groups[it->second].textures.size() == maxLayers) {
            open[size] = groups.size();
            groups.push_back({size.first, size.second, {}});
        }
        groups[open[size]].textures.push_back(i);
    }
    // Too many sizes: keep the most used ones (the fewest textures resampled) and share the rest, as
    // few slots of their largest size as hold them.
    TextureTablePlan plan;
    if (groups.size() > slots) {
        std::vector<size_t> order(groups.size());
        for (size_t k = 0; k < order.size(); ++k) order[k] = k;
        std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {  // ties: the larger keeps its size
            const TextureSlot &x = groups[a], &y = groups[b];
            if (x.textures.size() != y.textures.size()) return x.textures.size() > y.textures.size();
            return uint64_t(x.width) * x.height > uint64_t(y.width) * y.height;
        });
        for (uint32_t keep = slots - 1;; --keep) {
            std::vector<uint32_t> rest;
            uint32_t w = 1, h = 1;
            for (size_t k = keep; k < order.size(); ++k)
                for (uint32_t t : groups[order[k]].textures) {
                    rest.push_back(t);
                    w = std::max(w, textures[t].width), h = std::max(h, textures[t].height);
                }
            std::sort(rest.begin(), rest.end());
            const size_t shared = (rest.size() + maxLayers - 1) / maxLayers;
            if (keep + shared <= slots) {
                std::sort(order.begin(), order.begin() + keep);  // kept slots in order of first use
                for (size_t k = 0; k < keep; ++k) plan.slots.push_back(std::move(groups[order[k]]));
                for (size_t first = 0; first < rest.size(); first += maxLayers)
                    plan.slots.push_back({w, h, {rest.begin() + first, rest.begin() + std::min(rest.size(), first + maxLayers)}});
                plan.resampled = uint32_t(rest.size());
                break;
            }
            if (keep == 0)
                throw std::invalid_argument(fmt::format("the scene has {} textures: the material texture table holds "
                                                        "{} x {}", textures.size(), slots, maxLayers));
        }
    } else {
        plan.slots = std::move(groups);
    }
    plan.handles.assign(textures.size(), NO_TEXTURE);
    for (uint32_t s = 0; s < plan.slots.size(); ++s)
        for (uint32_t layer = 0; layer < plan.slots[s].textures.size(); ++layer)
            plan.handles[plan.slots[s].textures[layer]] = s | layer << TEXTURE_LAYER_SHIFT;
    return plan;
}

namespace {

// Level 0 of `layer`: a copy at the slot's size, else a blit from a copy at the texture's own.
void uploadLayer(vk::CommandContext& cmd, vk::Image& image, const Texture& t, uint32_t layer) {
    if (t.width == 0 || t.height == 0 || t.rgba8.size() != size_t(t.width) * t.height * 4)
        throw vk::VulkanError(fmt::format("texture layer {} of {} has no or inconsistent texels", layer,
                                          image.width()));
    vk::Allocator& alloc = cmd.allocator();
    vk::Buffer staging(alloc, t.rgba8.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true, "texture-staging");
    staging.write(t.rgba8.data(), t.rgba8.size());
    const bool ownSize = t.width == image.width() && t.height == image.height();
    vk::Image source;
    if (!ownSize)
        source = vk::Image(alloc, {kFormat, t.width, t.height, 1,
                                   VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                       VK_IMAGE_USAGE_SAMPLED_BIT,  // every vk::Image has a view
                                   "texture-source"});
    cmd.submitAndWait([&](VkCommandBuffer c) {
        vk::Image& target = ownSize ? image : source;
        vk::transitionImage(c, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, ownSize ? layer : 0, 1};
        copy.imageExtent = {t.width, t.height, 1};
        vkCmdCopyBufferToImage(c, staging.handle(), target.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
        if (ownSize) return;
        vk::transitionImage(c, source, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kTransfer, VK_ACCESS_2_TRANSFER_READ_BIT);
        vk::transitionImage(c, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        VkImageBlit r{};
        r.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        r.srcOffsets[1] = {int32_t(t.width), int32_t(t.height), 1};
        r.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, layer, 1};
        r.dstOffsets[1] = {int32_t(image.width()), int32_t(image.height()), 1};
        vkCmdBlitImage(c, source.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image.handle(),
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &r, VK_FILTER_LINEAR);
    });
}

}  // namespace

vk::Image uploadTextureSlot(vk::CommandContext& cmd, const std::vector<Texture>& textures, const TextureSlot& slot,
                            const char* name) {
    const uint32_t layers = std::max<uint32_t>(1, uint32_t(slot.textures.size()));
    vk::Image image(cmd.allocator(),
                    {kFormat, slot.width, slot.height, layers,
                     VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                     name, mipLevelCount(slot.width, slot.height), true});
    for (uint32_t layer = 0; layer < slot.textures.size(); ++layer)
        uploadLayer(cmd, image, textures.at(slot.textures[layer]), layer);
    cmd.submitAndWait([&](VkCommandBuffer c) {
        vk::transitionImage(c, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        buildMips(c, image);
    });
    return image;
}

}  // namespace penumbra
