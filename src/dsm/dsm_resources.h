// The GPU memory the deep-shadow-map passes and the lookup share, and how it is sized.
//
// Layout: DSM_HEAD_UINTS head pointers per texel (uint, DSM_NONE = empty list; after the resolve the
// sorted list's head and length) for every DSM layer (one layer per light with a DSM; deep opacity
// maps: one uint per texel); one node pool for all layers, a uvec4 per
// node (depth, alpha -> transmittance, next, right-neighbour link: see shared/types.h) plus a side
// uint per node: its depth again, packed, as the binary search's key (`--dsm-lookup search`), or its
// upper-neighbour link (`links`); one atomic counter that allocates nodes. The pool is allocated once at its full capacity; a frame
// uses the first `fragments` nodes.
#pragma once
#include <string>
#include <vector>

#include "dsm/dsm_settings.h"
#include "dsm/hair_gpu.h"

namespace penumbra {

// One map of a light with a deep shadow map: a directional or spot light has one, a point light six
// (the faces of a cube, +x, -x, +y, -y, +z, -z, consecutive).
struct DsmLayer {
    uint32_t light;
    LightProjection projection;  // the light's view of the whole scene, like its ordinary shadow map
    RibbonView view;
    bool cube = false;
    uint32_t face = 0;
};

struct DsmResources {
    uint32_t resolution = 1;
    uint64_t capacity = 1;  // nodes in the pool
    bool deviceLimited = false;  // the automatic size was cut to what the device addresses
    uint32_t maxList = 50;
    bool opacityMaps = false;   // deep opacity maps: node t holds texel t's layers (DeepOpacityBuildPass)
    float opacityLayer = 1.0f;  // their layer thickness (world units)
    std::vector<DsmLayer> layers;
    vk::BufferRing views;       // row k: layer k's viewProj (binding 0 of the build), per frame slot
    vk::BufferRing lightTable;  // GpuDsmLight per scene light, then per cube face, per frame slot
    vk::Buffer heads;       // DSM_HEAD_UINTS uints per texel and layer
    vk::Buffer nodes;       // uvec4 per node
    vk::Buffer side;        // uint per node: search key (depth bits) or upper link
    vk::Buffer runs;        // uvec2 per node: the build's (depth, alpha), grouped by texel (its second step)
    vk::Buffer buckets;     // bucketCount uints per texel and layer: node counts per depth bucket, then places
    uint32_t bucketCount = 1;  // kBuckets, or fewer where one buffer of them would not fit the device
    bool countsZeroed = false;  // buckets filled with 0 once (dsm.clear); then the resolve keeps them so
    vk::Buffer stats;       // DsmStats
    vk::Buffer work;        // the texels with nodes, for the resolve: uvec4 (x = count), then per texel a uvec2
                            // (texel, its sorted list's place in the pool)

    static constexpr VkDeviceSize kNodeBytes = sizeof(glm::uvec4) + sizeof(uint32_t) + sizeof(glm::uvec2);  // node + side + run
    static constexpr uint32_t kBuckets = DSM_BUCKETS;  // depth buckets per texel

    // The buffer sizes for `texels` texels of all layers, shared with the device budget so that what it
    // admits is what is allocated and bound. Each buffer is bound whole through one storage descriptor.
    static VkDeviceSize headBytes(uint64_t texels, bool opacityMaps) {
        return texels * sizeof(uint32_t) * (opacityMaps ? 1 : DSM_HEAD_UINTS);
    }
    // A uvec4 header (x = count), then a uvec2 per texel (deep opacity maps: the header only).
    static VkDeviceSize workBytes(uint64_t texels, bool opacityMaps) {
        return sizeof(glm::uvec4) + (opacityMaps ? 0 : texels * sizeof(glm::uvec2));
    }
    // The depth buckets per texel: kBuckets, halved until one buffer of them fits `storageBufferRange`.
    static uint32_t bucketCountFor(uint64_t texels, uint64_t storageBufferRange) {
        uint32_t count = kBuckets;
        while (count > 1 && bucketBytes(texels, count) > storageBufferRange) count /= 2;
        return count;
    }
    static VkDeviceSize bucketBytes(uint64_t texels, uint32_t bucketCount) { return texels * sizeof(uint32_t) * bucketCount; }
    // The maps' memory besides the node pool at the full bucket count (what the resolution rule and the
    // pool's share of memory reserve): heads, work list and kBuckets depth buckets (deep opacity maps: heads).
    static VkDeviceSize fixedBytes(uint64_t texels, bool opacityMaps) {
        return headBytes(texels, opacityMaps) + workBytes(texels, opacityMaps) +
               (opacityMaps ? sizeof(uint32_t) : bucketBytes(texels, kBuckets));
    }
    static VkDeviceSize nodeBufferBytes(uint64_t capacity) { return capacity * sizeof(glm::uvec4); }
    // The node pool: --dsm-nodes, a deep opacity map's one node per texel, or the automatic size clamped
    // to what the device takes beside the fixed part (a storage descriptor, an allocation, half its memory).
    static uint64_t poolCapacity(const DsmSettings& settings, uint64_t texels, const vk::DeviceLimits& limits);
    // --dsm-res, or by default the shadow maps' resolution halved until the maps' fixed part takes at
    // most a quarter of the device's memory and its work list fits one storage-buffer descriptor.
    static uint32_t resolutionFor(const DsmSettings& settings, uint32_t shadowResolution, uint32_t layers,
                                  const vk::DeviceLimits& limits);
    // How many maps `settings` gives `lights`: one per light with a DSM, six for a point light.
    static uint32_t layerCountFor(const DsmSettings& settings, const std::vector<Light>& lights);
    static bool hasDeepShadowMap(const DsmSettings& settings, const Light& light, uint32_t index);
    size_t lightCount_ = 1;

    // Allocates every buffer and writes the tables of every slot. Throws vk::VulkanError with a clear message
    // when the pool does not fit the device (storage-buffer range, allocation size, memory heap).
    DsmResources(vk::Allocator& alloc, const DsmSettings& settings, uint32_t resolution, std::vector<DsmLayer> layers,
                 size_t lightCount, float opacityLayer = 1.0f);

    uint32_t layerCount() const { return uint32_t(layers.size()); }
    // The push constants of the per-texel passes (offsets, resolve, link).
    gpu::DsmPush push() const {
        return {resolution, layerCount(), uint32_t(capacity), maxList, bucketCount, 0, 0, 0};
    }
    // Writes frame slot `slot`'s tables from the layers' current projections.
    void writeTables(const DsmSettings& settings, uint32_t slot);
    VkDeviceSize poolBytes() const { return nodes.size() + side.size() + runs.size(); }
    VkDeviceSize headBytes() const { return heads.size() + work.size() + buckets.size(); }
};

}  // namespace penumbra
