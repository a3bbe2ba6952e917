// Visibility rays through the occupancy volume (src/voxel/occupancy_volume.h). The includer defines
// OCCUPANCY_BINDING (a storage buffer of set 0) and includes shared/types.h first.
#ifndef PENUMBRA_OCCUPANCY_GLSL
#define PENUMBRA_OCCUPANCY_GLSL
layout(set = 0, binding = OCCUPANCY_BINDING, std430) readonly buffer OccupancyBits {
    GpuOccupancyGrid grid;
    uint bits[];
} occupancy;

float occupancyVoxelSize() { return occupancy.grid.origin.w; }

bool voxelOccupied(ivec3 c) {
    const ivec3 dims = ivec3(occupancy.grid.dims.xyz);
    if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, dims))) return false;  // outside: empty
    const uint index = uint(c.x) + uint(dims.x) * (uint(c.y) + uint(dims.y) * uint(c.z));
    return (occupancy.bits[index >> 5u] & (1u << (index & 31u))) != 0u;
}

// One step of a 3D DDA (Amanatides & Woo) walking a segment through the grid.
struct VoxelWalk {
    ivec3 cell, stepDir;
    vec3 tNext, tDelta;  // t along the segment at each axis' next voxel boundary, and between boundaries
    int stepsLeft;       // boundary crossings to the last voxel
    bool clear;          // no occupied voxel met so far
};

void walkStep(inout VoxelWalk w) {
    if (!w.clear || w.stepsLeft <= 0) return;
    if (w.tNext.x <= w.tNext.y && w.tNext.x <= w.tNext.z) {
        w.cell.x += w.stepDir.x;
        w.tNext.x += w.tDelta.x;
    } else if (w.tNext.y <= w.tNext.z) {
        w.cell.y += w.stepDir.y;
        w.tNext.y += w.tDelta.y;
    } else {
        w.cell.z += w.stepDir.z;
        w.tNext.z += w.tDelta.z;
    }
    --w.stepsLeft;
    w.clear = !voxelOccupied(w.cell);
}

// Whether the segment from world point a to world point b crosses no occupied voxel, leaving out
// `skip` voxels at each end (the shells of the surfaces the ends lie on or near: a surface occupies
// every voxel it touches). The DDA visits exactly the voxels the rest of the segment passes through.
// Eight steps per loop iteration: lavapipe ends a shader's loops silently after 65535 iterations in
// all (llvmpipe's LP_MAX_TGSI_LOOP_ITERATIONS), which a gather's hundreds of walks would reach.
bool segmentClear(vec3 a, vec3 b, float skip) {
    if (occupancy.grid.dims.x == 0u) return true;  // no volume bound
    const vec3 pa = (a - occupancy.grid.origin.xyz) / occupancy.grid.origin.w;
    const vec3 pb = (b - occupancy.grid.origin.xyz) / occupancy.grid.origin.w;
    const float len = length(pb - pa);
    if (len <= 2.0 * skip) return true;
    const vec3 dir = (pb - pa) / len;
    const vec3 p = pa + skip * dir, q = pb - skip * dir, d = q - p;
    VoxelWalk w;
    w.cell = ivec3(floor(p));
    w.stepDir = ivec3(sign(d));
    w.tDelta = 1.0 / max(abs(d), vec3(1e-12));
    w.tNext = mix(vec3(2.0), (vec3(w.cell) + vec3(greaterThan(d, vec3(0.0))) - p) * sign(d) * w.tDelta,
                  notEqual(w.stepDir, ivec3(0)));
    const ivec3 gap = abs(ivec3(floor(q)) - w.cell);
    w.stepsLeft = gap.x + gap.y + gap.z;
    w.clear = !voxelOccupied(w.cell);
    while (w.clear && w.stepsLeft > 0) {
        walkStep(w); walkStep(w); walkStep(w); walkStep(w);
        walkStep(w); walkStep(w); walkStep(w); walkStep(w);
    }
    return w.clear;
}
#endif
