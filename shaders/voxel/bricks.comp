#version 460
// The occupancy volume's brick bits (src/voxel/occupancy_volume.h): one thread per brick of
// OCCUPANCY_BRICK^3 voxels sets its bit where any of its voxels is occupied.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "voxel/bindings.h"

layout(local_size_x = 64) in;

layout(set = 0, binding = BRICKS_OCCUPANCY, std430) buffer Occupancy { GpuOccupancyGrid grid; uint bits[]; } occupancy;

void main() {
    const uvec3 dims = occupancy.grid.dims, bricks = dims / OCCUPANCY_BRICK;
    const uint brick = gl_GlobalInvocationID.x;
    if (brick >= bricks.x * bricks.y * bricks.z) return;
    const uvec3 b = uvec3(brick % bricks.x, (brick / bricks.x) % bricks.y, brick / (bricks.x * bricks.y));
    bool any = false;
    // A brick row of OCCUPANCY_BRICK voxels along x lies within one word (x is a multiple of 4).
    for (uint z = 0u; z < OCCUPANCY_BRICK && !any; ++z)
        for (uint y = 0u; y < OCCUPANCY_BRICK; ++y) {
            const uvec3 v = b * OCCUPANCY_BRICK + uvec3(0u, y, z);
            const uint index = v.x + dims.x * (v.y + dims.y * v.z);
            any = any || ((occupancy.bits[index >> 5u] >> (index & 31u)) & 0xFu) != 0u;
        }
    if (any) atomicOr(occupancy.bits[occupancy.grid.firstBrickWord + (brick >> 5u)], 1u << (brick & 31u));
}
