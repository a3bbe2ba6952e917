// Command recording helpers: one-shot submissions, image barriers, uploads and read-backs.
#pragma once
#include <functional>
#include <vector>

#include "vk/resources.h"

namespace penumbra::vk {

// One layout transition of `range` of a raw image handle (swapchain images, mip ranges) with the given
// scopes; the layer that tracks no state for it.
void imageBarrier(VkCommandBuffer cmd, VkImage image, const VkImageSubresourceRange& range, VkImageLayout from,
                  VkImageLayout to, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                  VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);

// Records a barrier from the image's last use (its ImageState) to the given use, and updates it.
void transitionImage(VkCommandBuffer cmd, Image& image, VkImageLayout layout, VkPipelineStageFlags2 stage,
                     VkAccessFlags2 access);

// A global memory barrier for buffer hazards (buffers are few; per-buffer ranges buy nothing here).
void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);

class CommandContext {
public:
    explicit CommandContext(Allocator& alloc);
    ~CommandContext();
    CommandContext(const CommandContext&) = delete;
    CommandContext& operator=(const CommandContext&) = delete;

    // Records `fn` into a fresh command buffer, submits it and waits for completion.
    void submitAndWait(const std::function<void(VkCommandBuffer)>& fn);

    // Device-local buffer filled with `bytes` through a staging buffer.
    Buffer createDeviceBuffer(const void* data, VkDeviceSize bytes, VkBufferUsageFlags usage, const char* name = "");
    // Fills an image from `data` with the given copy regions (buffer offsets into `data`), leaves
    // it SHADER_READ_ONLY. The short form fills layer 0, level 0 from tightly packed texels.
    void uploadImage(Image& image, const void* data, VkDeviceSize bytes,
                     const std::vector<VkBufferImageCopy>& regions);
    void uploadImage(Image& image, const void* data, VkDeviceSize bytes);
    // Copies layer `layer` of an image into host memory (tightly packed texels).
    std::vector<uint8_t> readImage(Image& image, uint32_t texelBytes, uint32_t layer = 0);
    std::vector<uint8_t> readBuffer(const Buffer& buffer, VkDeviceSize bytes);

    Allocator& allocator() { return alloc_; }

private:
    Allocator& alloc_;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
};

}  // namespace penumbra::vk
