// The occupancy volume: the scene's surfaces as one bit per voxel of a box around the scene, for
// visibility rays that cost a few hundred bytes of reads instead of a BVH (the RSM gather's
// VPL-to-receiver visibility: --rsm-visibility voxels). Opaque and alpha-masked triangles occupy the
// voxels they touch (conservative: no ray passes between two voxels of one surface); blended ones
// and hair do not, as they let light through.
// The sky's facing bits: a single-sided triangle blocks light only where its front faces the light
// (the shadow maps cull back faces), so a sky dome whose fronts face inward lets the sky in while a
// closed building still blocks it (by its far side). The sky's rays all go up, and a voxel keeps,
// for each azimuth quadrant of theirs (signs of x and z), whether it blocks them: four bits a voxel,
// made where the scene has single-sided triangles (the sky's rays read the voxel bits otherwise).
// A double-sided triangle blocks every quadrant; a single-sided one those whose middle direction
// (+-1, 1, +-1) / sqrt(3) runs along its front normal n. That is exact for horizontal triangles and
// for walls facing +-x or +-z (the plane dot(n, d) = 0 then bounds no quadrant's interior). Otherwise
// the rays of a quadrant on the far side of that plane from its middle direction are wrongly blocked
// or passed: a wall facing a diagonal wrongly passes half the rays of the two quadrants beside the
// one it faces; a roof facing +x at 45 degrees passes every ray with x < 0, though it would block
// those steeper than 45 degrees (they leave it from behind: from under an open roof). The RSM's
// visibility and LPV read the voxel bits, where every surface blocks.
//   occupancy.clear           the grid header, zero bits, an empty chunk list (transfer)
//   occupancy.voxelize        every drawn triangle into the bits (shaders/voxel/voxelize.comp); those
//                             over many voxel columns listed as chunks of columns
//   occupancy.voxelize-large  the listed chunks, one workgroup each (indirect)
//   occupancy.bricks          a bit per 4^3 voxels where any is set (shaders/voxel/bricks.comp)
// They run only when the volume is stale: at the first frame and after invalidate() (instances
// moved: the Renderer calls it with its cached shadow layers). The buffer ("occupancy": a
// GpuOccupancyGrid, then the bits) is read with shaders/voxel/occupancy.glsl.
#pragma once
#include "core/frame_graph.h"
#include "core/scene_gpu.h"
#include "shared/types.h"

namespace penumbra {

// The grid around `bounds`: cubic voxels, `resolution` along the box's longest side, one voxel of
// margin on every side (so surfaces on the box's faces lie inside), each side rounded up to whole
// bricks.
gpu::GpuOccupancyGrid occupancyGrid(const Bounds& bounds, uint32_t resolution);

// Whether any voxelized triangle (not blended) is single-sided: then the volume has facing bits.
bool hasSingleSidedSurfaces(const Scene& scene);

class OccupancyVolume {
public:
    OccupancyVolume(vk::Allocator& alloc, SceneGpu& scene, uint32_t resolution);
    // The buffer's size: the header, the voxel and brick bits, and the sky's facing bits if asked.
    static uint64_t bytes(const Bounds& bounds, uint32_t resolution, bool skyFacing);
    void invalidate() { stale_ = true; }
    // How many builds addTo() has declared: what depends on the voxels redoes its work when it changes.
    uint64_t generation() const { return generation_; }
    // Declares the build when stale and publishes "occupancy".
    void addTo(FrameGraph& graph);

    const gpu::GpuOccupancyGrid& grid() const { return grid_; }
    const vk::Buffer& buffer() const { return buffer_; }  // read-back for tests

private:
    void addVoxelize(FrameGraph& graph, const char* name, BufferHandle volume, BufferHandle chunks, bool listed);

    SceneGpu& scene_;
    gpu::GpuOccupancyGrid grid_;
    uint32_t brickCount_ = 0;
    vk::ComputeKernel voxelize_, bricks_;
    vk::Buffer buffer_, chunks_;  // the bits; the large triangles' chunks (and their dispatch's arguments)
    bool stale_ = true;
    uint64_t generation_ = 0;
};

}  // namespace penumbra
