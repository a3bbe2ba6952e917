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
// Where the scene has single-sided triangles the sky's facing bits follow (from skyFirstWord on; 0:
// none, the sky reads the voxel bits): OCCUPANCY_SKY_QUADRANTS bits per voxel, voxel i's at bits
// 4 (i % 8) .. 4 (i % 8) + 3 of word skyFirstWord + i / 8, bit q set where the voxel blocks the sky's
// rays of azimuth quadrant q (occupancySkyQuadrant). A single-sided triangle blocks light only where
// its front faces the light (the shadow maps' rule); src/voxel/occupancy_volume.h says how a quadrant
// stands for its rays.
struct GpuOccupancyGrid {
    vec3 origin;          // the world position of voxel (0, 0, 0)'s lower corner
    float voxelSize;      // m
    uvec3 dims;           // voxels per axis (multiples of OCCUPANCY_BRICK)
    uint firstBrickWord;  // index of the first brick word
    uint skyFirstWord;    // index of the first word of the sky's facing bits; 0: none
    uint pad0, pad1, pad2;
};
#define OCCUPANCY_BRICK 4
#define OCCUPANCY_SKY_QUADRANTS 4   // azimuth quadrants of the sky's rays: bit 0 x > 0, bit 1 z > 0
#define OCCUPANCY_SKY_VOXELS_PER_WORD 8
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
static_assert(sizeof(GpuOccupancyGrid) == 48 && offsetof(GpuOccupancyGrid, voxelSize) == 12 &&
              offsetof(GpuOccupancyGrid, dims) == 16 && offsetof(GpuOccupancyGrid, firstBrickWord) == 28 &&
              offsetof(GpuOccupancyGrid, skyFirstWord) == 32);
static_assert(OCCUPANCY_SKY_QUADRANTS * OCCUPANCY_SKY_VOXELS_PER_WORD == 32);
}  // namespace penumbra::gpu
#endif
#endif
