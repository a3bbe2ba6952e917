#include "voxel/occupancy_volume.h"

#include <algorithm>
#include <cmath>

#include "voxel/bindings.h"

namespace penumbra {
namespace {

constexpr uint32_t kChunkCapacity = 1u << 18;  // large-triangle chunks listed per build (2 MiB)

// Words of the voxel bits and the bricks' bits; then, with facing bits, where those start and end.
struct OccupancyWords {
    uint64_t skyFirst = 0, total = 0;
};

OccupancyWords occupancyWords(const gpu::GpuOccupancyGrid& grid, bool skyFacing) {
    const glm::uvec3 bricks = glm::uvec3(grid.dims) / uint32_t(OCCUPANCY_BRICK);
    const uint64_t brickCount = uint64_t(bricks.x) * bricks.y * bricks.z;
    OccupancyWords w;
    w.total = uint64_t(grid.firstBrickWord) + (brickCount + 31) / 32;
    if (!skyFacing) return w;
    const uint64_t voxels = uint64_t(grid.dims.x) * grid.dims.y * grid.dims.z;
    w.skyFirst = w.total;
    w.total += (voxels + OCCUPANCY_SKY_VOXELS_PER_WORD - 1) / OCCUPANCY_SKY_VOXELS_PER_WORD;
    return w;
}

}  // namespace

bool hasSingleSidedSurfaces(const Scene& scene) {
    for (const Draw& d : scene.draws) {
        if (d.indexCount == 0 || d.material >= scene.materials.size()) continue;
        const Material& m = scene.materials[d.material];
        if (!m.doubleSided && m.alphaMode != AlphaMode::Blend) return true;  // blended ones are not voxels
    }
    return false;
}

uint64_t OccupancyVolume::bytes(const Bounds& bounds, uint32_t resolution, bool skyFacing) {
    return sizeof(gpu::GpuOccupancyGrid) + occupancyWords(occupancyGrid(bounds, resolution), skyFacing).total * 4;
}

gpu::GpuOccupancyGrid occupancyGrid(const Bounds& bounds, uint32_t resolution) {
    const glm::vec3 extent = glm::max(bounds.max - bounds.min, glm::vec3(1e-3f));
    const uint32_t inner = std::max(resolution, 3u) - 2;  // the margin's two voxels come out of it
    const float voxel = std::max({extent.x, extent.y, extent.z}) / float(inner);
    const glm::uvec3 fit = glm::uvec3(glm::ceil(extent / voxel)) + 2u;
    const glm::uvec3 dims = (fit + uint32_t(OCCUPANCY_BRICK - 1)) / uint32_t(OCCUPANCY_BRICK) * uint32_t(OCCUPANCY_BRICK);
    const glm::vec3 origin = bounds.center() - 0.5f * voxel * glm::vec3(dims);
    const uint64_t voxels = uint64_t(dims.x) * dims.y * dims.z;
    return {origin, voxel, dims, uint32_t((voxels + 31) / 32), 0, 0, 0, 0};
}

OccupancyVolume::OccupancyVolume(vk::Allocator& alloc, SceneGpu& scene, uint32_t resolution)
    : scene_(scene), grid_(occupancyGrid(scene.scene().bounds, resolution)) {
    std::vector<vk::Binding> bindings;  // materials, the bits, the chunks, then the instances and triangles
    for (uint32_t k : {VOXELIZE_MATERIALS, VOXELIZE_OCCUPANCY, VOXELIZE_CHUNKS, SCENE_INSTANCES_BINDING, SCENE_VERTICES,
                       SCENE_INDICES, SCENE_TRIANGLE_MATERIALS, SCENE_DRAWN_TRIANGLES})
        bindings.push_back({k, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
    vk::Context& ctx = alloc.context();
    voxelize_ = vk::ComputeKernel(ctx, "voxel/voxelize.comp", bindings, sizeof(gpu::OccupancyPush));
    bricks_ = vk::ComputeKernel(ctx, "voxel/bricks.comp",
                                std::vector<vk::Binding>{{BRICKS_OCCUPANCY, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}}, 0);
    const glm::uvec3 bricks = glm::uvec3(grid_.dims) / uint32_t(OCCUPANCY_BRICK);
    brickCount_ = bricks.x * bricks.y * bricks.z;
    const OccupancyWords words = occupancyWords(grid_, hasSingleSidedSurfaces(scene.scene()));
    grid_.skyFirstWord = uint32_t(words.skyFirst);
    const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    buffer_ = vk::Buffer(alloc, sizeof(gpu::GpuOccupancyGrid) + words.total * 4,
                         usage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, false, "occupancy");
    chunks_ = vk::Buffer(alloc, sizeof(glm::uvec4) + sizeof(glm::uvec2) * kChunkCapacity,
                         usage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, false, "occupancy-chunks");
}

void OccupancyVolume::addTo(FrameGraph& graph) {
    const BufferHandle volume = graph.import(buffer_);
    graph.publish("occupancy", volume);
    if (!stale_) return;
    stale_ = false;
    ++generation_;
    const BufferHandle chunks = graph.import(chunks_);
    const gpu::GpuOccupancyGrid grid = grid_;
    graph.pass("occupancy.clear", PassKind::Transfer)
        .use(volume, Use::TransferDst)
        .use(chunks, Use::TransferDst)
        .record([volume, chunks, grid](PassContext& c) {
            const VkBuffer b = c.buffer(volume).handle();
            vkCmdUpdateBuffer(c.cmd, b, 0, sizeof(grid), &grid);
            vkCmdFillBuffer(c.cmd, b, sizeof(grid), VK_WHOLE_SIZE, 0);
            const glm::uvec4 args(0, 1, 1, 0);  // no chunk yet; a dispatch's y and z
            vkCmdUpdateBuffer(c.cmd, c.buffer(chunks).handle(), 0, sizeof(args), &args);
        });
    addVoxelize(graph, "occupancy.voxelize", volume, chunks, false);
    addVoxelize(graph, "occupancy.voxelize-large", volume, chunks, true);
    graph.pass("occupancy.bricks")
        .pipeline(bricks_.pipeline)
        .storageBuffer(BRICKS_OCCUPANCY, volume, Use::StorageWrite)
        .record([count = brickCount_](PassContext& c) { vkCmdDispatch(c.cmd, vk::divUp(count, 64u), 1, 1); });
}

// The triangles (small ones walked, large ones listed as chunks), or the listed chunks.
void OccupancyVolume::addVoxelize(FrameGraph& graph, const char* name, BufferHandle volume, BufferHandle chunks,
                                  bool listed) {
    const uint32_t triangles = scene_.drawnTriangleCount();
    PassBuilder pass = graph.pass(name);
    pass.pipeline(voxelize_.pipeline)
        .storageBuffer(VOXELIZE_MATERIALS, graph.import(scene_.materials()))
        .storageBuffer(SCENE_INSTANCES_BINDING, scene_.instanceTable(graph))
        .storageBuffer(VOXELIZE_OCCUPANCY, volume, Use::StorageWrite)
        .storageBuffer(VOXELIZE_CHUNKS, chunks, listed ? Use::StorageRead : Use::StorageWrite);
    if (listed) pass.use(chunks, Use::IndirectArgs);
    scene_.declareTriangles(pass);
    pass.record([this, triangles, listed, chunks](PassContext& c) {
        const gpu::OccupancyPush push{triangles, listed ? 1u : 0u, kChunkCapacity, 0};
        voxelize_.pipeline.push(c.cmd, push);
        if (listed) {
            vkCmdDispatchIndirect(c.cmd, c.buffer(chunks).handle(), 0);
            return;
        }
        const uint32_t groups = vk::divUp(std::max(triangles, 1u), OCCUPANCY_GROUP);
        const uint32_t x = std::min(groups, 65535u);
        vkCmdDispatch(c.cmd, x, vk::divUp(groups, x), 1);
    });
}

}  // namespace penumbra
