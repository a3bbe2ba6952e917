#include "vk/memory.h"

#include <fmt/format.h>

namespace penumbra::vk {

Allocator::Allocator(Context& ctx, VkDeviceSize blockSize) : ctx_(ctx), blockSize_(blockSize) {
    vkGetPhysicalDeviceMemoryProperties(ctx.physicalDevice(), &props_);
    // Buffers and optimal-tiling images may share a block: keep them a granularity apart.
    granularity_ = ctx.properties().limits.bufferImageGranularity;
}

Allocator::~Allocator() {
    for (Block& b : blocks_)
        if (b.memory) vkFreeMemory(ctx_.device(), b.memory, nullptr);
}

uint32_t Allocator::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required,
                                   VkMemoryPropertyFlags preferred) const {
    uint32_t fallback = UINT32_MAX;
    for (uint32_t i = 0; i < props_.memoryTypeCount; ++i) {
        if (!(typeBits & (1u << i))) continue;
        VkMemoryPropertyFlags f = props_.memoryTypes[i].propertyFlags;
        if ((f & required) != required) continue;
        if ((f & preferred) == preferred) return i;
        if (fallback == UINT32_MAX) fallback = i;
    }
    if (fallback == UINT32_MAX) throw VulkanError(fmt::format("no memory type with properties {:#x}", required));
    return fallback;
}

bool Allocator::tryAllocate(Block& b, VkDeviceSize size, VkDeviceSize align, VkDeviceSize& offset) {
    for (auto it = b.freeRanges.begin(); it != b.freeRanges.end(); ++it) {
        VkDeviceSize start = (it->first + align - 1) / align * align;
        VkDeviceSize end = it->first + it->second;
        if (start + size > end) continue;
        VkDeviceSize rangeStart = it->first;
        b.freeRanges.erase(it);
        if (start > rangeStart) b.freeRanges[rangeStart] = start - rangeStart;
        if (start + size < end) b.freeRanges[start + size] = end - (start + size);
        offset = start;
        return true;
    }
    return false;
}

uint32_t Allocator::newBlock(uint32_t memoryType, VkDeviceSize size) {
    Block b;
    b.size = size;
    b.memoryType = memoryType;
    VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    ai.allocationSize = size;
    ai.memoryTypeIndex = memoryType;
    VK_CHECK(vkAllocateMemory(ctx_.device(), &ai, nullptr, &b.memory));
    if (props_.memoryTypes[memoryType].propertyFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) {
        void* p = nullptr;
        VK_CHECK(vkMapMemory(ctx_.device(), b.memory, 0, VK_WHOLE_SIZE, 0, &p));
        b.mapped = static_cast<uint8_t*>(p);
    }
    b.freeRanges[0] = size;
    blocks_.push_back(std::move(b));
    return static_cast<uint32_t>(blocks_.size() - 1);
}

Allocation Allocator::allocate(const VkMemoryRequirements& req, VkMemoryPropertyFlags required,
                               VkMemoryPropertyFlags preferred) {
    const uint32_t type = findMemoryType(req.memoryTypeBits, required, preferred);
    const VkDeviceSize align = std::max(req.alignment, granularity_);
    const VkDeviceSize size = (req.size + align - 1) / align * align;
    VkDeviceSize offset = 0;
    uint32_t blockIndex = UINT32_MAX;
    for (uint32_t i = 0; i < blocks_.size() && blockIndex == UINT32_MAX; ++i)
        if (blocks_[i].memory && blocks_[i].memoryType == type && tryAllocate(blocks_[i], size, align, offset))
            blockIndex = i;
    if (blockIndex == UINT32_MAX) {
        blockIndex = newBlock(type, std::max(blockSize_, size));
        if (!tryAllocate(blocks_[blockIndex], size, align, offset)) throw VulkanError("allocator: block too small");
    }
    Block& b = blocks_[blockIndex];
    inUse_ += size;
    ++allocations_;
    return Allocation{b.memory, offset, size, b.mapped ? b.mapped + offset : nullptr, type, blockIndex};
}

void Allocator::free(const Allocation& a) {
    if (a.block == UINT32_MAX) return;
    Block& b = blocks_[a.block];
    inUse_ -= a.size;
    auto [it, inserted] = b.freeRanges.emplace(a.offset, a.size);
    // Coalesce with the following and the preceding free range.
    auto next = std::next(it);
    if (next != b.freeRanges.end() && it->first + it->second == next->first) {
        it->second += next->second;
        b.freeRanges.erase(next);
    }
    if (it != b.freeRanges.begin()) {
        auto prev = std::prev(it);
        if (prev->first + prev->second == it->first) {
            prev->second += it->second;
            b.freeRanges.erase(it);
        }
    }
}

VkDeviceSize Allocator::bytesReserved() const {
    VkDeviceSize total = 0;
    for (const Block& b : blocks_) total += b.size;
    return total;
}

}  // namespace penumbra::vk
