// Visibility rays through the occupancy volume (src/voxel/occupancy_volume.h). The includer defines
// OCCUPANCY_BINDING (a storage buffer of set 0) and includes shared/types.h first.
#ifndef PENUMBRA_OCCUPANCY_GLSL
#define PENUMBRA_OCCUPANCY_GLSL
layout(set = 0, binding = OCCUPANCY_BINDING, std430) readonly buffer OccupancyBits {
    GpuOccupancyGrid grid;
    uint bits[];
} occupancy;

float occupancyVoxelSize() { return occupancy.grid.voxelSize; }

// Which rays a walk asks about: OCCUPANCY_EVERY_RAY (every voxel with a surface blocks), or the sky's
// azimuth quadrant of an upward ray (occupancySkyQuadrant).
const uint OCCUPANCY_EVERY_RAY = 0xFFFFFFFFu;

// The sky's facing bit of an upward ray along d: bit 0 for d.x > 0, bit 1 for d.z > 0.
uint occupancySkyQuadrant(vec3 d) { return (d.x > 0.0 ? 1u : 0u) + (d.z > 0.0 ? 2u : 0u); }

// Whether voxel c blocks the rays `quadrant` stands for; without facing bits (no single-sided
// triangle in the scene) every occupied voxel blocks every ray.
bool voxelBlocks(ivec3 c, uint quadrant) {
    const ivec3 dims = ivec3(occupancy.grid.dims);
    if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, dims))) return false;  // outside: empty
    const uint index = uint(c.x) + uint(dims.x) * (uint(c.y) + uint(dims.y) * uint(c.z));
    if (quadrant == OCCUPANCY_EVERY_RAY || occupancy.grid.skyFirstWord == 0u)
        return (occupancy.bits[index >> 5u] & (1u << (index & 31u))) != 0u;
    const uint word = occupancy.grid.skyFirstWord + index / OCCUPANCY_SKY_VOXELS_PER_WORD;
    const uint bit = (index % OCCUPANCY_SKY_VOXELS_PER_WORD) * OCCUPANCY_SKY_QUADRANTS + quadrant;
    return (occupancy.bits[word] & (1u << bit)) != 0u;
}

bool voxelOccupied(ivec3 c) { return voxelBlocks(c, OCCUPANCY_EVERY_RAY); }

bool brickOccupied(ivec3 b) {
    const ivec3 bricks = ivec3(occupancy.grid.dims) / OCCUPANCY_BRICK;
    if (any(lessThan(b, ivec3(0))) || any(greaterThanEqual(b, bricks))) return false;
    const uint index = uint(b.x) + uint(bricks.x) * (uint(b.y) + uint(bricks.y) * uint(b.z));
    return (occupancy.bits[occupancy.grid.firstBrickWord + (index >> 5u)] & (1u << (index & 31u))) != 0u;
}

// A segment p + t d, t in [0, 1] (voxel units), walked through the grid: empty bricks in one step
// each, occupied ones voxel by voxel (a 3D DDA, Amanatides & Woo, visiting exactly the voxels the
// segment passes through).
struct VoxelRay {
    vec3 p, d, invD;
    bvec3 moves;     // the axes along which d is not 0
    float t;         // where the walk stands
    bool inBrick;    // walking the voxels of an occupied brick
    ivec3 cell, brick;
    vec3 tNext;      // inBrick: t at the next voxel boundary of each axis
    uint quadrant;   // the rays the voxels are asked about (voxelBlocks)
    bool clear, done;
};

const float kRayEpsilon = 1e-5;  // in t: past a boundary, into the next brick or voxel

void rayStep(inout VoxelRay r) {
    if (r.done) return;
    const vec3 dirPositive = vec3(greaterThan(r.d, vec3(0.0)));
    if (!r.inBrick) {
        const vec3 at = r.p + r.d * (r.t + kRayEpsilon);
        r.brick = ivec3(floor(at / float(OCCUPANCY_BRICK)));
        if (brickOccupied(r.brick)) {
            r.inBrick = true;
            r.cell = ivec3(floor(at));
            r.tNext = mix(vec3(2.0), (vec3(r.cell) + dirPositive - r.p) * r.invD, r.moves);
            return;
        }
        const vec3 exits = (vec3(r.brick * OCCUPANCY_BRICK) + dirPositive * float(OCCUPANCY_BRICK) - r.p) * r.invD;
        const vec3 t = mix(vec3(2.0), exits, r.moves);
        r.t = max(min(t.x, min(t.y, t.z)), r.t + kRayEpsilon);  // forward, whatever the rounding
        r.done = r.t >= 1.0;
        return;
    }
    if (voxelBlocks(r.cell, r.quadrant)) {
        r.clear = false;
        r.done = true;
        return;
    }
    const float tExit = min(r.tNext.x, min(r.tNext.y, r.tNext.z));
    if (tExit >= 1.0) {
        r.done = true;
        return;
    }
    const ivec3 stepAxis = tExit == r.tNext.x ? ivec3(1, 0, 0) : (tExit == r.tNext.y ? ivec3(0, 1, 0) : ivec3(0, 0, 1));
    r.cell += stepAxis * ivec3(sign(r.d));
    r.tNext += vec3(stepAxis) * abs(r.invD);
    r.t = tExit;
    r.inBrick = all(equal(r.cell / OCCUPANCY_BRICK, r.brick)) && all(greaterThanEqual(r.cell, ivec3(0)));
}

// Whether the segment from world point a to world point b crosses no voxel that blocks `quadrant`'s
// rays, leaving out `skip` voxels at each end (the shells of the surfaces the ends lie on or near: a
// surface occupies every voxel it touches). Four steps per loop iteration: lavapipe ends a shader's
// loops silently after 65535 iterations in all (llvmpipe's LP_MAX_TGSI_LOOP_ITERATIONS), which a
// gather's hundreds of walks would reach. The bricks' bits are the voxel bits', a superset of any
// quadrant's: a brick empty for every ray is crossed in one step.
bool segmentClearFor(vec3 a, vec3 b, float skip, uint quadrant) {
    if (occupancy.grid.dims.x == 0u) return true;  // no volume bound
    const vec3 pa = (a - occupancy.grid.origin) / occupancy.grid.voxelSize;
    const vec3 pb = (b - occupancy.grid.origin) / occupancy.grid.voxelSize;
    const float len = length(pb - pa);
    if (len <= 2.0 * skip) return true;
    const vec3 dir = (pb - pa) / len;
    VoxelRay r;
    r.p = pa + skip * dir;
    r.d = (pb - skip * dir) - r.p;
    r.moves = notEqual(r.d, vec3(0.0));
    r.invD = 1.0 / mix(vec3(1.0), r.d, r.moves);
    r.t = 0.0;
    r.inBrick = false;
    r.quadrant = quadrant;
    r.clear = true;
    r.done = false;
    for (int i = 0; i < 1024 && !r.done; ++i) {  // at most 4096 steps: ends even if rounding stalls it
        rayStep(r); rayStep(r); rayStep(r); rayStep(r);
    }
    return r.clear;
}

// Whether the segment crosses no occupied voxel (every surface blocks).
bool segmentClear(vec3 a, vec3 b, float skip) { return segmentClearFor(a, b, skip, OCCUPANCY_EVERY_RAY); }

// Whether the sky's light reaches a along the upward segment a -> b: voxels block by the facing of
// their single-sided triangles (the shadow maps' rule), by the quadrant of b - a.
bool skySegmentClear(vec3 a, vec3 b, float skip) { return segmentClearFor(a, b, skip, occupancySkyQuadrant(b - a)); }
#endif
