#include "voxel/occupancy_volume.h"

#include <algorithm>
#include <cmath>

namespace penumbra {

gpu::GpuOccupancyGrid occupancyGrid(const Bounds& bounds, uint32_t resolution) {
    const glm::vec3 extent = glm::max(bounds.max - bounds.min, glm::vec3(1e-3f));
    const uint32_t inner = std::max(resolution, 3u) - 2;  // the margin's two voxels come out of it
    const float voxel = std::max({extent.x, extent.y, extent.z}) / float(inner);
    const glm::uvec3 dims = glm::uvec3(glm::ceil(extent / voxel)) + 2u;
    const glm::vec3 origin = bounds.center() - 0.5f * voxel * glm::vec3(dims);
    return {glm::vec4(origin, voxel), glm::uvec4(dims, 0)};
}

OccupancyVolume::OccupancyVolume(vk::Allocator& alloc, SceneGpu& scene, uint32_t resolution)
    : scene_(scene), grid_(occupancyGrid(scene.scene().bounds, resolution)) {
    std::vector<vk::Binding> bindings;  // materials, the bits, then the instances and triangles
    for (uint32_t k : {1u, 2u, uint32_t(SCENE_INSTANCES_BINDING), 12u, 13u, 14u, 16u})
        bindings.push_back({k, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
    voxelize_ = vk::ComputeKernel(alloc.context(), "voxel/voxelize.comp", bindings, sizeof(gpu::OccupancyPush));
    const VkDeviceSize voxels = VkDeviceSize(grid_.dims.x) * grid_.dims.y * grid_.dims.z;
    buffer_ = vk::Buffer(alloc, sizeof(gpu::GpuOccupancyGrid) + (voxels + 31) / 32 * 4,
                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                             VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                         false, "occupancy");
}

void OccupancyVolume::addTo(FrameGraph& graph) {
    const BufferHandle volume = graph.import(buffer_);
    graph.publish("occupancy", volume);
    if (!stale_) return;
    stale_ = false;
    const gpu::GpuOccupancyGrid grid = grid_;
    graph.pass("occupancy.clear", PassKind::Transfer).use(volume, Use::TransferDst).record([volume, grid](PassContext& c) {
        const VkBuffer b = c.buffer(volume).handle();
        vkCmdUpdateBuffer(c.cmd, b, 0, sizeof(grid), &grid);
        vkCmdFillBuffer(c.cmd, b, sizeof(grid), VK_WHOLE_SIZE, 0);
    });
    const uint32_t triangles = scene_.drawnTriangleCount();
    PassBuilder pass = graph.pass("occupancy.voxelize");
    pass.pipeline(voxelize_.pipeline)
        .storageBuffer(1, graph.import(scene_.materials()))
        .storageBuffer(SCENE_INSTANCES_BINDING, scene_.instanceTable(graph))
        .storageBuffer(2, volume, Use::StorageWrite);
    scene_.declareTriangles(pass);
    pass.record([this, triangles](PassContext& c) {
        const gpu::OccupancyPush push{{triangles, 0, 0, 0}};
        voxelize_.pipeline.push(c.cmd, push);
        const uint32_t groups = vk::divUp(std::max(triangles, 1u), OCCUPANCY_GROUP);
        const uint32_t x = std::min(groups, 65535u);
        vkCmdDispatch(c.cmd, x, vk::divUp(groups, x), 1);
    });
}

}  // namespace penumbra
