// Buffers, images and samplers: move-only owners of a Vulkan handle and its memory.
// Images remember their last layout/stage/access so that the frame graph can emit barriers.
#pragma once
#include <cstring>
#include <string>
#include <vector>

#include "vk/memory.h"

namespace penumbra::vk {

class Buffer {
public:
    Buffer() = default;
    // Host-visible buffers are persistently mapped (mapped() != nullptr).
    Buffer(Allocator& alloc, VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible, const char* name = "");
    ~Buffer() { reset(); }
    Buffer(Buffer&& o) noexcept { *this = std::move(o); }
    Buffer& operator=(Buffer&& o) noexcept;

    VkBuffer handle() const { return buffer_; }
    VkDeviceSize size() const { return size_; }
    uint8_t* mapped() const { return alloc_.mapped; }
    template <class T> T* as() const { return reinterpret_cast<T*>(alloc_.mapped); }
    void write(const void* data, VkDeviceSize bytes, VkDeviceSize offset = 0);
    explicit operator bool() const { return buffer_ != VK_NULL_HANDLE; }
    const std::string& name() const { return name_; }
    void reset();

private:
    Allocator* allocator_ = nullptr;
    std::string name_;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceSize size_ = 0;
    Allocation alloc_;
};

// Host-visible copies of one buffer, one per frame in flight: the host writes the copy of the frame
// it records while the GPU may still read the others. select() picks the copy for the frame slot.
inline constexpr uint32_t kMaxFramesInFlight = 3;

class BufferRing {
public:
    BufferRing() = default;
    BufferRing(Allocator& alloc, VkDeviceSize size, VkBufferUsageFlags usage, const char* name = "");
    void select(uint32_t slot) { slot_ = slot; }
    Buffer& current() { return copies_[slot_]; }
    const Buffer& at(uint32_t slot) const { return copies_[slot]; }
    const Buffer& current() const { return copies_[slot_]; }
    void write(const void* data, VkDeviceSize bytes) { current().write(data, bytes); }
    explicit operator bool() const { return bool(copies_[0]); }

private:
    Buffer copies_[kMaxFramesInFlight];
    uint32_t slot_ = 0;
};

struct ImageDesc {
    VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
    uint32_t width = 1, height = 1, layers = 1;
    VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT;
    const char* name = "";
    uint32_t mipLevels = 1;
    bool arrayView = false;  // view() is a 2D array even with one layer (sampler2DArray*)
};

// Last use of an image, for barrier generation.
struct ImageState {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;
};

class Image {
public:
    Image() = default;
    Image(Allocator& alloc, const ImageDesc& desc);
    ~Image() { reset(); }
    Image(Image&& o) noexcept { *this = std::move(o); }
    Image& operator=(Image&& o) noexcept;

    VkImage handle() const { return image_; }
    VkImageView view() const { return view_; }          // all layers (2D or 2D array)
    VkImageView layerView(uint32_t layer) const { return layerViews_.at(layer); }  // one layer as 2D
    VkFormat format() const { return desc_.format; }
    uint32_t width() const { return desc_.width; }
    uint32_t height() const { return desc_.height; }
    uint32_t layers() const { return desc_.layers; }
    uint32_t mipLevels() const { return desc_.mipLevels; }
    VkImageSubresourceRange fullRange() const { return {aspect(), 0, desc_.mipLevels, 0, desc_.layers}; }
    VkExtent2D extent() const { return {desc_.width, desc_.height}; }
    VkImageAspectFlags aspect() const;
    const std::string& name() const { return name_; }
    ImageState& state() { return state_; }
    VkDeviceSize bytes() const { return alloc_.size; }
    explicit operator bool() const { return image_ != VK_NULL_HANDLE; }
    void reset();

private:
    Allocator* allocator_ = nullptr;
    VkImage image_ = VK_NULL_HANDLE;
    VkImageView view_ = VK_NULL_HANDLE;
    std::vector<VkImageView> layerViews_;
    ImageDesc desc_;
    std::string name_;
    Allocation alloc_;
    ImageState state_;
};

struct SamplerDesc {
    VkFilter filter = VK_FILTER_LINEAR;
    VkSamplerAddressMode address = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    bool compare = false;  // depth comparison sampler (shadow maps)
    bool mipmaps = false;
};

class Sampler {
public:
    Sampler() = default;
    Sampler(Context& ctx, const SamplerDesc& desc);
    ~Sampler() { reset(); }
    Sampler(Sampler&& o) noexcept { *this = std::move(o); }
    Sampler& operator=(Sampler&& o) noexcept;
    VkSampler handle() const { return sampler_; }
    void reset();

private:
    VkDevice device_ = VK_NULL_HANDLE;
    VkSampler sampler_ = VK_NULL_HANDLE;
};

bool isDepthFormat(VkFormat f);

}  // namespace penumbra::vk
