#include "dsm/dsm_resources.h"

#include <algorithm>
#include <string>

#include <fmt/format.h>

namespace penumbra {
namespace {

constexpr double kMiB = 1024.0 * 1024.0;

// The maps' fixed part (`fixed`: heads, work list, depth buckets) must leave half of the device's
// memory to spare, and the pool must be addressable by one storage-buffer descriptor, allocatable in
// one piece, and fit what the fixed part leaves of that half: refuse either with the numbers rather
// than fail inside the driver.
void checkFits(vk::Context& ctx, uint64_t capacity, VkDeviceSize fixed, const DsmSettings& settings, uint32_t res,
               size_t maps) {
    const vk::DeviceLimits& lim = ctx.limits();
    if (fixed > lim.deviceMemory / 2)
        throw vk::VulkanError(fmt::format("--dsm-res {}: {} deep shadow map(s) need {:.0f} MiB of list heads, work list "
                                          "and depth buckets, more than half of the device's memory ({:.0f} MiB)",
                                          res, maps, double(fixed) / kMiB, double(lim.deviceMemory / 2) / kMiB));
    const VkDeviceSize nodeBytes = VkDeviceSize(capacity) * 16, total = VkDeviceSize(capacity) * DsmResources::kNodeBytes + fixed;
    struct Check {
        VkDeviceSize need, limit;
        const char* what;
    };
    const std::string pool = settings.poolNodes ? fmt::format("--dsm-nodes {}", capacity) : "--dsm-res " + std::to_string(res);
    for (const Check& c : {Check{nodeBytes, lim.storageBufferRange, "the device's storage-buffer range"},
                           Check{nodeBytes, lim.allocationSize, "the device's largest allocation"},
                           Check{total, lim.deviceMemory / 2, "half of the device's memory"}})
        if (c.need > c.limit)
            throw vk::VulkanError(fmt::format("{}: the deep-shadow-map node pool and lists need {:.0f} MiB, more than {} "
                                              "({:.0f} MiB)",
                                              pool, double(c.need) / kMiB, c.what, double(c.limit) / kMiB));
}

// The largest pool the device takes beside the maps' fixed part (the automatic size is clamped to it).
uint64_t maxNodes(vk::Context& ctx, VkDeviceSize fixed) {
    const vk::DeviceLimits& lim = ctx.limits();
    const uint64_t half = lim.deviceMemory / 2;
    const uint64_t forHeap = half > fixed ? (half - fixed) / DsmResources::kNodeBytes : 0;
    return std::max<uint64_t>(1, std::min({lim.storageBufferRange / 16, lim.allocationSize / 16, forHeap}));
}

gpu::GpuDsmLight tableEntry(const DsmLayer& layer, int index, uint32_t resolution, const DsmSettings& s,
                            float opacityLayer) {
    gpu::GpuDsmLight g{};
    g.viewProj = layer.projection.viewProj;
    g.viewer = layer.view.viewer;
    g.texelSize = layer.projection.texelSize;
    g.projection = layer.projection.perspective ? DSM_PROJECTION_PERSPECTIVE : DSM_PROJECTION_ORTHO;
    g.layer = index;
    g.resolution = resolution;
    g.filterWidth = s.filterWidth;
    g.depthBias = s.depthBias;
    g.normalOffset = s.normalOffset;
    g.opacityMaps = s.opacityMaps ? 1u : 0u;
    g.layerThickness = opacityLayer;
    g.binarySearch = s.lookup == DsmLookup::Search ? 1u : 0u;
    return g;
}

}  // namespace

DsmResources::DsmResources(vk::Allocator& alloc, const DsmSettings& settings, uint32_t res,
                           std::vector<DsmLayer> dsmLayers, size_t lightCount, float domLayer)
    : resolution(res), maxList(settings.maxList), opacityMaps(settings.opacityMaps), opacityLayer(domLayer),
      layers(std::move(dsmLayers)) {
    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    const VkBufferUsageFlags cleared = storage | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    const uint64_t texels = uint64_t(res) * res * std::max<size_t>(layers.size(), 1);
    const VkDeviceSize fixed = layers.empty() ? 0 : fixedBytes(texels, opacityMaps);
    const uint64_t automatic = std::min({texels * DsmSettings::kAutoNodesPerTexel, DsmSettings::kMaxPoolNodes - 1,
                                         maxNodes(alloc.context(), fixed)});
    capacity = layers.empty() ? 1 : opacityMaps ? texels : settings.poolNodes ? settings.poolNodes : automatic;
    deviceLimited = !layers.empty() && !opacityMaps && !settings.poolNodes && automatic < texels * DsmSettings::kAutoNodesPerTexel;
    const uint64_t headBytes = texels * 4 * (opacityMaps ? 1 : DSM_HEAD_UINTS);
    if (!layers.empty()) checkFits(alloc.context(), capacity, fixed, settings, res, layers.size());  // --dsm-res, --dsm-nodes
    heads = vk::Buffer(alloc, layers.empty() ? 4 : headBytes, cleared, false, "dsm-heads");
    nodes = vk::Buffer(alloc, capacity * 16, cleared, false, "dsm-nodes");
    side = vk::Buffer(alloc, opacityMaps ? 4 : capacity * 4, cleared, false, "dsm-side");  // DOM: unused
    stats = vk::Buffer(alloc, sizeof(gpu::DsmStats), cleared, false, "dsm-stats");
    work = vk::Buffer(alloc, opacityMaps || layers.empty() ? 16 : 16 + headBytes, cleared, false, "dsm-work");
    runs = vk::Buffer(alloc, opacityMaps ? 8 : capacity * 8, cleared, false, "dsm-runs");  // DOM: unused
    bucketCount = depthBucketCount(alloc.context(), texels, kBuckets);
    buckets = vk::Buffer(alloc, opacityMaps || layers.empty() ? 4 : texels * 4 * bucketCount, cleared, false,
                         "dsm-buckets");

    views = vk::BufferRing(alloc, std::max<size_t>(layers.size(), 1) * sizeof(glm::mat4), storage, "dsm-views");
    const size_t faces = size_t(std::count_if(layers.begin(), layers.end(), [](const DsmLayer& l) { return l.cube; }));
    lightTable = vk::BufferRing(alloc, (std::max<size_t>(lightCount, 1) + faces) * sizeof(gpu::GpuDsmLight), storage,
                               "dsm-lights");
    lightCount_ = std::max<size_t>(lightCount, 1);
    for (uint32_t slot = 0; slot < vk::kMaxFramesInFlight; ++slot) writeTables(settings, slot);
}

void DsmResources::writeTables(const DsmSettings& settings, uint32_t slot) {
    std::vector<glm::mat4> rows{glm::mat4(1.0f)};
    std::vector<gpu::GpuDsmLight> table(lightCount_);
    for (gpu::GpuDsmLight& g : table) g.layer = -1, g.resolution = resolution;  // no DSM
    for (size_t i = 0; i < layers.size(); ++i) {
        const gpu::GpuDsmLight entry = tableEntry(layers[i], int(i), resolution, settings, opacityLayer);
        if (!layers[i].cube) {
            table.at(layers[i].light) = entry;
        } else {
            // A point light's entry names its first face's; the faces follow the lights' entries.
            if (layers[i].face == 0) {
                gpu::GpuDsmLight cube = entry;
                cube.projection = DSM_PROJECTION_CUBE;
                cube.firstFace = uint32_t(table.size());
                table.at(layers[i].light) = cube;
            }
            table.push_back(entry);
        }
        if (i == 0) rows.clear();
        rows.push_back(layers[i].projection.viewProj);
    }
    views.select(slot);
    lightTable.select(slot);
    views.write(rows.data(), rows.size() * sizeof(glm::mat4));
    lightTable.write(table.data(), table.size() * sizeof(gpu::GpuDsmLight));
}

}  // namespace penumbra
