#include "vk/resources.h"

#include <utility>

namespace penumbra::vk {

Buffer::Buffer(Allocator& alloc, VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible, const char* name)
    : allocator_(&alloc), name_(name), size_(size) {
    VkBufferCreateInfo ci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    ci.size = size ? size : 16;
    ci.usage = usage;
    ci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkDevice dev = alloc.context().device();
    VK_CHECK(vkCreateBuffer(dev, &ci, nullptr, &buffer_));
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(dev, buffer_, &req);
    alloc_ = hostVisible
                 ? alloc.allocate(req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                                  VK_MEMORY_PROPERTY_HOST_CACHED_BIT)
                 : alloc.allocate(req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VK_CHECK(vkBindBufferMemory(dev, buffer_, alloc_.memory, alloc_.offset));
    alloc.context().debugUtils().name(VK_OBJECT_TYPE_BUFFER, buffer_, name);
}

Buffer& Buffer::operator=(Buffer&& o) noexcept {
    if (this != &o) {
        reset();
        allocator_ = std::exchange(o.allocator_, nullptr);
        name_ = std::move(o.name_);
        buffer_ = std::exchange(o.buffer_, VK_NULL_HANDLE);
        size_ = std::exchange(o.size_, 0);
        alloc_ = std::exchange(o.alloc_, Allocation{});
    }
    return *this;
}

void Buffer::write(const void* data, VkDeviceSize bytes, VkDeviceSize offset) {
    if (!alloc_.mapped) throw VulkanError("Buffer::write on a buffer that is not host-visible");
    if (offset + bytes > size_) throw VulkanError("Buffer::write past the end of the buffer");
    std::memcpy(alloc_.mapped + offset, data, bytes);
}

void Buffer::reset() {
    if (buffer_) {
        vkDestroyBuffer(allocator_->context().device(), buffer_, nullptr);
        allocator_->free(alloc_);
    }
    buffer_ = VK_NULL_HANDLE;
    alloc_ = {};
}

BufferRing::BufferRing(Allocator& alloc, VkDeviceSize size, VkBufferUsageFlags usage, const char* name) {
    for (Buffer& b : copies_) b = Buffer(alloc, size, usage, true, name);
}

bool isDepthFormat(VkFormat f) {
    return f == VK_FORMAT_D32_SFLOAT || f == VK_FORMAT_D16_UNORM || f == VK_FORMAT_D24_UNORM_S8_UINT ||
           f == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

VkImageAspectFlags Image::aspect() const {
    return isDepthFormat(desc_.format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

Image::Image(Allocator& alloc, const ImageDesc& desc) : allocator_(&alloc), desc_(desc), name_(desc.name) {
    VkImageCreateInfo ci{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ci.imageType = VK_IMAGE_TYPE_2D;
    ci.format = desc.format;
    ci.extent = {desc.width, desc.height, 1};
    ci.mipLevels = desc.mipLevels;
    ci.arrayLayers = desc.layers;
    ci.samples = VK_SAMPLE_COUNT_1_BIT;
    ci.tiling = VK_IMAGE_TILING_OPTIMAL;
    ci.usage = desc.usage;
    ci.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkDevice dev = alloc.context().device();
    VK_CHECK(vkCreateImage(dev, &ci, nullptr, &image_));
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(dev, image_, &req);
    alloc_ = alloc.allocate(req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VK_CHECK(vkBindImageMemory(dev, image_, alloc_.memory, alloc_.offset));
    alloc.context().debugUtils().name(VK_OBJECT_TYPE_IMAGE, image_, desc.name);

    VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vi.image = image_;
    vi.viewType = desc.layers > 1 || desc.arrayView ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
    vi.format = desc.format;
    vi.subresourceRange = fullRange();
    VK_CHECK(vkCreateImageView(dev, &vi, nullptr, &view_));
    if (desc.layers > 1 || desc.arrayView) {
        for (uint32_t l = 0; l < desc.layers; ++l) {
            vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
            vi.subresourceRange = {aspect(), 0, desc.mipLevels, l, 1};
            VkImageView v;
            VK_CHECK(vkCreateImageView(dev, &vi, nullptr, &v));
            layerViews_.push_back(v);
        }
    } else {
        layerViews_.push_back(view_);
    }
}

Image& Image::operator=(Image&& o) noexcept {
    if (this != &o) {
        reset();
        allocator_ = std::exchange(o.allocator_, nullptr);
        image_ = std::exchange(o.image_, VK_NULL_HANDLE);
        view_ = std::exchange(o.view_, VK_NULL_HANDLE);
        layerViews_ = std::move(o.layerViews_);
        desc_ = o.desc_;
        name_ = std::move(o.name_);
        alloc_ = std::exchange(o.alloc_, Allocation{});
        state_ = o.state_;
    }
    return *this;
}

void Image::reset() {
    if (image_) {
        VkDevice dev = allocator_->context().device();
        for (VkImageView v : layerViews_)
            if (v != view_) vkDestroyImageView(dev, v, nullptr);
        vkDestroyImageView(dev, view_, nullptr);
        vkDestroyImage(dev, image_, nullptr);
        allocator_->free(alloc_);
    }
    image_ = VK_NULL_HANDLE;
    view_ = VK_NULL_HANDLE;
    layerViews_.clear();
    alloc_ = {};
}

Sampler::Sampler(Context& ctx, const SamplerDesc& d) : device_(ctx.device()) {
    VkSamplerCreateInfo ci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    ci.magFilter = ci.minFilter = d.filter;
    ci.mipmapMode = d.mipmaps ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
    ci.addressModeU = ci.addressModeV = ci.addressModeW = d.address;
    ci.compareEnable = d.compare;
    ci.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;  // lit when receiver depth <= stored depth
    ci.maxLod = d.mipmaps ? VK_LOD_CLAMP_NONE : 0.0f;
    ci.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;  // outside the map: unshadowed
    VK_CHECK(vkCreateSampler(device_, &ci, nullptr, &sampler_));
}

Sampler& Sampler::operator=(Sampler&& o) noexcept {
    if (this != &o) {
        reset();
        device_ = o.device_;
        sampler_ = std::exchange(o.sampler_, VK_NULL_HANDLE);
    }
    return *this;
}

void Sampler::reset() {
    if (sampler_) vkDestroySampler(device_, sampler_, nullptr);
    sampler_ = VK_NULL_HANDLE;
}

}  // namespace penumbra::vk
