// The occupancy volume (src/voxel): the structs and constants its passes share between C++ and GLSL,
// laid out by the rules of shared/types.h, which includes this file (its includers see them all).
#ifndef PENUMBRA_VOXEL_TYPES_H
#define PENUMBRA_VOXEL_TYPES_H

#include "shared/types.h"

#ifdef __cplusplus
namespace penumbra::gpu {
#endif

// The occupancy volume (src/voxel): one bit per voxel of a box around the scene, set where a surface
// (opaque or alpha-masked; not blended, not hair) touches the voxel. Voxel (x, y, z) is bit
// (x + dims.x (y + dims.y z)) of the bit words after this header.
// Bricks of OCCUPANCY_BRICK^3 voxels have a bit each too (after the voxels' words, from
// firstBrickWord on), set where any of their voxels is: rays cross empty bricks in one step.
struct GpuOccupancyGrid {
    vec3 origin;          // the world position of voxel (0, 0, 0)'s lower corner
    float voxelSize;      // m
    uvec3 dims;           // voxels per axis (multiples of OCCUPANCY_BRICK)
    uint firstBrickWord;  // index of the first brick word
};
#define OCCUPANCY_BRICK 4
#define OCCUPANCY_GROUP 64          // voxelize.comp: threads (triangles) per workgroup
#define OCCUPANCY_SMALL_COLUMNS 16  // a triangle over more columns is cut into chunks of
#define OCCUPANCY_CHUNK_COLUMNS 256 // this many, one workgroup each (a wall covers tens of thousands)

struct OccupancyPush {
    uint triangleCount;  // drawn triangles
    uint walkChunks;     // 1: walk the chunk list (else the triangles)
    uint chunkCapacity;
    uint pad0;
};

#ifdef __cplusplus
static_assert(sizeof(OccupancyPush) == 16);
static_assert(sizeof(GpuOccupancyGrid) == 32 && offsetof(GpuOccupancyGrid, voxelSize) == 12 &&
              offsetof(GpuOccupancyGrid, dims) == 16 && offsetof(GpuOccupancyGrid, firstBrickWord) == 28);
}  // namespace penumbra::gpu
#endif
#endif
