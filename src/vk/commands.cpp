#include "vk/commands.h"

#include <cstring>

#include "vk/shader_registry.h"

namespace penumbra::vk {

const EmbeddedShader& findShader(const std::string& key) {
    for (const EmbeddedShader* s = kEmbeddedShaders; s->key; ++s)
        if (key == s->key) return *s;
    throw VulkanError("no embedded shader named " + key);
}

void imageBarrier(VkCommandBuffer cmd, VkImage image, const VkImageSubresourceRange& range, VkImageLayout from,
                  VkImageLayout to, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                  VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
    VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    b.srcStageMask = srcStage;
    b.srcAccessMask = srcAccess;
    b.dstStageMask = dstStage;
    b.dstAccessMask = dstAccess;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = range;
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = 1;
    dep.pImageMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &dep);
}

void transitionImage(VkCommandBuffer cmd, Image& image, VkImageLayout layout, VkPipelineStageFlags2 stage,
                     VkAccessFlags2 access) {
    ImageState& s = image.state();
    imageBarrier(cmd, image.handle(), image.fullRange(), s.layout, layout,
                 s.stage ? s.stage : VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, s.access, stage, access);
    s = {layout, stage, access};
}

void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
    VkMemoryBarrier2 b{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    b.srcStageMask = srcStage;
    b.srcAccessMask = srcAccess;
    b.dstStageMask = dstStage;
    b.dstAccessMask = dstAccess;
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.memoryBarrierCount = 1;
    dep.pMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &dep);
}

CommandContext::CommandContext(Allocator& alloc) : alloc_(alloc) {
    Context& ctx = alloc.context();
    VkCommandPoolCreateInfo ci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    ci.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT | VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    ci.queueFamilyIndex = ctx.queueFamily();
    VK_CHECK(vkCreateCommandPool(ctx.device(), &ci, nullptr, &pool_));
    VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(ctx.device(), &fi, nullptr, &fence_));
}

CommandContext::~CommandContext() {
    VkDevice dev = alloc_.context().device();
    vkDestroyFence(dev, fence_, nullptr);
    vkDestroyCommandPool(dev, pool_, nullptr);
}

void CommandContext::submitAndWait(const std::function<void(VkCommandBuffer)>& fn) {
    Context& ctx = alloc_.context();
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = pool_;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    VkCommandBuffer cmd;
    VK_CHECK(vkAllocateCommandBuffers(ctx.device(), &ai, &cmd));
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(cmd, &bi));
    fn(cmd);
    VK_CHECK(vkEndCommandBuffer(cmd));
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = 1;
    si.pCommandBuffers = &cmd;
    VK_CHECK(vkQueueSubmit(ctx.queue(), 1, &si, fence_));
    VK_CHECK(vkWaitForFences(ctx.device(), 1, &fence_, VK_TRUE, UINT64_MAX));
    VK_CHECK(vkResetFences(ctx.device(), 1, &fence_));
    vkFreeCommandBuffers(ctx.device(), pool_, 1, &cmd);
}

Buffer CommandContext::createDeviceBuffer(const void* data, VkDeviceSize bytes, VkBufferUsageFlags usage,
                                          const char* name) {
    Buffer dst(alloc_, bytes, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, false, name);
    if (bytes == 0) return dst;
    Buffer staging(alloc_, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true, "upload-staging");
    staging.write(data, bytes);
    submitAndWait([&](VkCommandBuffer cmd) {
        VkBufferCopy region{0, 0, bytes};
        vkCmdCopyBuffer(cmd, staging.handle(), dst.handle(), 1, &region);
    });
    return dst;
}

void CommandContext::uploadImage(Image& image, const void* data, VkDeviceSize bytes) {
    VkBufferImageCopy region{};
    region.imageSubresource = {image.aspect(), 0, 0, 1};
    region.imageExtent = {image.width(), image.height(), 1};
    uploadImage(image, data, bytes, {region});
}

void CommandContext::uploadImage(Image& image, const void* data, VkDeviceSize bytes,
                                 const std::vector<VkBufferImageCopy>& regions) {
    Buffer staging(alloc_, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true, "upload-staging");
    staging.write(data, bytes);
    submitAndWait([&](VkCommandBuffer cmd) {
        transitionImage(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT);
        vkCmdCopyBufferToImage(cmd, staging.handle(), image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                               static_cast<uint32_t>(regions.size()), regions.data());
        transitionImage(cmd, image, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                        VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    });
}

std::vector<uint8_t> CommandContext::readImage(Image& image, uint32_t texelBytes, uint32_t layer) {
    const VkDeviceSize bytes = VkDeviceSize(image.width()) * image.height() * texelBytes;
    Buffer staging(alloc_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true, "readback-staging");
    submitAndWait([&](VkCommandBuffer cmd) {
        transitionImage(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                        VK_ACCESS_2_TRANSFER_READ_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {image.aspect(), 0, layer, 1};
        region.imageExtent = {image.width(), image.height(), 1};
        vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.handle(), 1,
                               &region);
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                      VK_ACCESS_2_HOST_READ_BIT);
    });
    return {staging.mapped(), staging.mapped() + bytes};
}

std::vector<uint8_t> CommandContext::readBuffer(const Buffer& buffer, VkDeviceSize bytes) {
    Buffer staging(alloc_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true, "readback-staging");
    submitAndWait([&](VkCommandBuffer cmd) {
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
        VkBufferCopy region{0, 0, bytes};
        vkCmdCopyBuffer(cmd, buffer.handle(), staging.handle(), 1, &region);
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                      VK_ACCESS_2_HOST_READ_BIT);
    });
    return {staging.mapped(), staging.mapped() + bytes};
}

}  // namespace penumbra::vk
