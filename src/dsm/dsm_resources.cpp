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
void checkFits(const vk::DeviceLimits& lim, uint64_t capacity, uint64_t texels, const DsmSettings& settings,
               uint32_t res, size_t maps) {
    const VkDeviceSize fixed = DsmResources::fixedBytes(texels, settings.opacityMaps);
    const VkDeviceSize work = DsmResources::workBytes(texels, settings.opacityMaps);
    if (work > lim.storageBufferRange)
        throw vk::VulkanError(fmt::format("{{dsm.resolution}} {}: {} deep shadow map(s) need a {:.0f} MiB work list, more than "
                                          "the device's storage-buffer range ({:.0f} MiB)",
                                          res, maps, double(work) / kMiB, double(lim.storageBufferRange) / kMiB));
    if (fixed > lim.deviceMemory / 2)
        throw vk::VulkanError(fmt::format("{{dsm.resolution}} {}: {} deep shadow map(s) need {:.0f} MiB of list heads, work list "
                                          "and depth buckets, more than half of the device's memory ({:.0f} MiB)",
                                          res, maps, double(fixed) / kMiB, double(lim.deviceMemory / 2) / kMiB));
    const VkDeviceSize nodeBytes = DsmResources::nodeBufferBytes(capacity), total = VkDeviceSize(capacity) * DsmResources::kNodeBytes + fixed;
    struct Check {
        VkDeviceSize need, limit;
        const char* what;
    };
    const std::string pool = settings.poolNodes ? fmt::format("{{dsm.pool_nodes}} {}", capacity) : fmt::format("{{dsm.resolution}} {}", res);
    for (const Check& c : {Check{nodeBytes, lim.storageBufferRange, "the device's storage-buffer range"},
                           Check{nodeBytes, lim.allocationSize, "the device's largest allocation"},
                           Check{total, lim.deviceMemory / 2, "half of the device's memory"}})
        if (c.need > c.limit)
            throw vk::VulkanError(fmt::format("{}: the deep-shadow-map node pool and lists need {:.0f} MiB, more than {} "
                                              "({:.0f} MiB)",
                                              pool, double(c.need) / kMiB, c.what, double(c.limit) / kMiB));
}

// The largest pool the device takes beside the maps' fixed part (the automatic size is clamped to it).
uint64_t maxNodes(const vk::DeviceLimits& lim, VkDeviceSize fixed) {
    const uint64_t half = lim.deviceMemory / 2;
    const uint64_t forHeap = half > fixed ? (half - fixed) / DsmResources::kNodeBytes : 0;
    const uint64_t perNode = DsmResources::nodeBufferBytes(1);
    return std::max<uint64_t>(1, std::min({lim.storageBufferRange / perNode, lim.allocationSize / perNode, forHeap}));
}

gpu::GpuDsmLight tableEntry(const DsmLayer& layer, int index, uint32_t resolution, const DsmSettings& s,
                            float opacityLayer) {
    gpu::GpuDsmLight g{};
    g.viewProj = layer.projection.viewProj;
    g.viewer = layer.view.viewer;
    g.viewerIsPoint = layer.view.viewerIsPoint;
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
    const vk::DeviceLimits& lim = alloc.context().limits();
    capacity = layers.empty() ? 1 : poolCapacity(settings, texels, lim);
    deviceLimited = !layers.empty() && !opacityMaps && !settings.poolNodes &&
                    capacity < texels * DsmSettings::kAutoNodesPerTexel;
    if (!layers.empty())  // --dsm-res, --dsm-nodes
        checkFits(lim, capacity, texels, settings, res, layers.size());
    const bool lists = !opacityMaps && !layers.empty();  // DOM: the side, runs, work and buckets are unused
    bucketCount = bucketCountFor(texels, lim.storageBufferRange);
    heads = vk::Buffer(alloc, layers.empty() ? 4 : headBytes(texels, opacityMaps), cleared, false, "dsm-heads");
    nodes = vk::Buffer(alloc, nodeBufferBytes(capacity), cleared, false, "dsm-nodes");
    side = vk::Buffer(alloc, lists ? capacity * sizeof(uint32_t) : 4, cleared, false, "dsm-side");
    stats = vk::Buffer(alloc, sizeof(gpu::DsmStats), cleared, false, "dsm-stats");
    work = vk::Buffer(alloc, workBytes(texels, !lists), cleared, false, "dsm-work");
    runs = vk::Buffer(alloc, lists ? capacity * sizeof(glm::uvec2) : 8, cleared, false, "dsm-runs");
    buckets = vk::Buffer(alloc, lists ? bucketBytes(texels, bucketCount) : 4, cleared, false, "dsm-buckets");

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

uint64_t DsmResources::poolCapacity(const DsmSettings& settings, uint64_t texels, const vk::DeviceLimits& limits) {
    if (settings.opacityMaps) return texels;
    if (settings.poolNodes) return settings.poolNodes;
    return std::min({texels * DsmSettings::kAutoNodesPerTexel, DsmSettings::kMaxPoolNodes - 1,
                     maxNodes(limits, fixedBytes(texels, false))});
}

uint32_t DsmResources::resolutionFor(const DsmSettings& settings, uint32_t shadowResolution, uint32_t layers,
                                     const vk::DeviceLimits& limits) {
    if (settings.resolution) return settings.resolution;
    uint32_t res = shadowResolution;
    auto fixed = [&](uint64_t r) { return fixedBytes(r * r * layers, settings.opacityMaps); };
    auto work = [&](uint64_t r) { return workBytes(r * r * layers, settings.opacityMaps); };
    while (res > 256 && (fixed(res) > limits.deviceMemory / 4 || work(res) > limits.storageBufferRange)) res /= 2;
    return res;
}

bool DsmResources::hasDeepShadowMap(const DsmSettings& settings, const Light& light, uint32_t index) {
    if (!settings.enabled) return false;
    if (settings.lights.empty()) return light.castsShadow;
    return std::find(settings.lights.begin(), settings.lights.end(), index) != settings.lights.end();
}

uint32_t DsmResources::layerCountFor(const DsmSettings& settings, const std::vector<Light>& lights) {
    uint32_t count = 0;
    for (uint32_t i = 0; i < lights.size(); ++i)
        if (hasDeepShadowMap(settings, lights[i], i)) count += lights[i].type == LightType::Point ? 6 : 1;
    return count;
}

}  // namespace penumbra
