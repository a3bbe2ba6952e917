// A small device-memory allocator: one vkAllocateMemory per large block, sub-allocated first-fit
// with coalescing free ranges. Host-visible blocks stay mapped for their lifetime.
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "vk/context.h"

namespace penumbra::vk {

struct Allocation {
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize offset = 0;
    VkDeviceSize size = 0;
    uint8_t* mapped = nullptr;  // non-null for host-visible memory
    uint32_t memoryType = UINT32_MAX;
    uint32_t block = UINT32_MAX;
};

class Allocator {
public:
    explicit Allocator(Context& ctx, VkDeviceSize blockSize = VkDeviceSize(64) << 20);
    ~Allocator();
    Allocator(const Allocator&) = delete;
    Allocator& operator=(const Allocator&) = delete;

    // `required` must all be present; `preferred` are taken when some memory type offers them.
    Allocation allocate(const VkMemoryRequirements& req, VkMemoryPropertyFlags required,
                        VkMemoryPropertyFlags preferred = 0);
    void free(const Allocation& a);

    Context& context() const { return ctx_; }
    VkDeviceSize bytesReserved() const;  // device memory held in blocks
    VkDeviceSize bytesInUse() const { return inUse_; }
    // Lifetime counters, for tests that check what a settings change allocates.
    uint64_t allocations() const { return allocations_; }      // allocate() calls
    uint32_t blockCount() const { return uint32_t(blocks_.size()); }

private:
    struct Block {
        VkDeviceMemory memory = VK_NULL_HANDLE;
        VkDeviceSize size = 0;
        uint32_t memoryType = 0;
        uint8_t* mapped = nullptr;
        std::map<VkDeviceSize, VkDeviceSize> freeRanges;  // offset -> size
    };
    uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) const;
    bool tryAllocate(Block& b, VkDeviceSize size, VkDeviceSize align, VkDeviceSize& offset);
    uint32_t newBlock(uint32_t memoryType, VkDeviceSize size);

    Context& ctx_;
    VkDeviceSize blockSize_;
    VkDeviceSize granularity_;
    VkPhysicalDeviceMemoryProperties props_{};
    std::vector<Block> blocks_;
    VkDeviceSize inUse_ = 0;
    uint64_t allocations_ = 0;
};

}  // namespace penumbra::vk
