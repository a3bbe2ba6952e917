#include "lighting/sky_background.h"

#include <cmath>
#include <vector>

#include <glm/gtc/packing.hpp>

namespace penumbra {

SkyBackground::SkyBackground(vk::Allocator& alloc) {
    image_ = vk::Image(alloc, {VK_FORMAT_R16G16B16A16_SFLOAT, kWidth, kHeight, 1,
                               VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, "sky.background"});
    staging_ = vk::BufferRing(alloc, VkDeviceSize(kWidth) * kHeight * 8, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                              "sky.background-staging");
}

// Radiance at texel centres of the layout, in world directions (sky.h: theta from +Y, phi = 0
// toward -Z).
void SkyBackground::fill(const Sky& sky, uint32_t slot) {
    constexpr double kPi = 3.14159265358979323846;
    std::vector<uint16_t> texels(size_t(kWidth) * kHeight * 4);
    for (uint32_t r = 0; r < kHeight; ++r) {
        const double theta = kPi * (r + 0.5) / kHeight;
        for (uint32_t c = 0; c < kWidth; ++c) {
            const double phi = 2.0 * kPi * (c + 0.5) / kWidth - kPi;
            const glm::vec3 d(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
            const glm::vec3 l = glm::min(sky.radiance(d), glm::vec3(65000.0f));  // the half float's range
            uint16_t* t = &texels[(size_t(r) * kWidth + c) * 4];
            t[0] = glm::packHalf1x16(l.r), t[1] = glm::packHalf1x16(l.g), t[2] = glm::packHalf1x16(l.b);
            t[3] = glm::packHalf1x16(1.0f);
        }
    }
    staging_.select(slot);
    staging_.write(texels.data(), texels.size() * sizeof(uint16_t));
    pendingSlot_ = int(slot);
}

ImageHandle SkyBackground::addTo(FrameGraph& graph) {
    const ImageHandle image = graph.import(image_);
    if (pendingSlot_ < 0) return image;
    const BufferHandle source = graph.import(staging_.at(uint32_t(pendingSlot_)));
    pendingSlot_ = -1;
    graph.pass("sky.upload", PassKind::Transfer)
        .use(source, Use::TransferSrc)
        .use(image, Use::TransferDst)
        .record([source, image](PassContext& c) {
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageExtent = {kWidth, kHeight, 1};
            vkCmdCopyBufferToImage(c.cmd, c.buffer(source).handle(), c.image(image).handle(),
                                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        });
    return image;
}

}  // namespace penumbra
