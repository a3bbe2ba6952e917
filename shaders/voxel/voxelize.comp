#version 460
// Conservative surface voxelization of every drawn triangle into the occupancy volume's bits
// (src/voxel/occupancy_volume.h): exactly the voxels a triangle meets. A triangle is walked over the
// voxel columns of its dominant axis (the axis its normal is closest to): a column whose square
// overlaps the triangle's projection (2D separating axes) has at most three candidate voxels, where
// the plane crosses above the square (its slope is <= 1 along both other axes); each candidate is
// then tested in 3D (triangleMeetsVoxel).
// A triangle over at most OCCUPANCY_SMALL_COLUMNS columns is walked by its own thread; larger ones
// are cut into chunks of OCCUPANCY_CHUNK_COLUMNS columns, listed for a second, indirect dispatch
// (pc.walkChunks = 1) of one workgroup per chunk. A full list leaves the triangle to its own thread.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "core/triangles.glsl"
#include "voxel/bindings.h"

layout(local_size_x = OCCUPANCY_GROUP) in;

layout(set = 0, binding = VOXELIZE_MATERIALS, std430) readonly buffer Materials { GpuMaterial materials[]; };
layout(set = 0, binding = VOXELIZE_OCCUPANCY, std430) buffer Occupancy { GpuOccupancyGrid grid; uint bits[]; } occupancy;
// x = chunks listed (the indirect dispatch's x; y = z = 1), then (triangle, first column) per chunk.
layout(set = 0, binding = VOXELIZE_CHUNKS, std430) buffer Chunks { uvec4 args; uvec2 chunks[]; } list;
layout(push_constant) uniform Push { OccupancyPush pc; };

struct Walk {
    vec3 v[3];        // the triangle in voxel units
    ivec3 axes;       // u, v, w: w the dominant axis
    vec3 normal;      // in (u, v, w) order
    ivec2 lo, size;   // its columns' box on (u, v), clamped to the grid
    vec2 wRange;      // its extent along w
    uint skyFacing;   // the sky's azimuth quadrants it blocks (skyFacing())
};

// The quadrants of upward rays a triangle of material m and front normal n (world space) blocks, a
// bit each (voxel/types.h). Double-sided: every one. Single-sided: those whose middle direction
// (+-1, 1, +-1) / sqrt(3), the mean upward direction of the quadrant, runs along the front
// (dot > 0: the light behind it sees its front); src/voxel/occupancy_volume.h states the error.
uint skyFacing(GpuMaterial m, vec3 n) {
    if (m.doubleSided != 0u) return (1u << OCCUPANCY_SKY_QUADRANTS) - 1u;
    uint bits = 0u;
    for (uint q = 0u; q < OCCUPANCY_SKY_QUADRANTS; ++q) {
        const vec3 middle = vec3((q & 1u) != 0u ? 1.0 : -1.0, 1.0, (q & 2u) != 0u ? 1.0 : -1.0);
        if (dot(n, middle) > 0.0) bits |= 1u << q;
    }
    return bits;
}

// The triangle `drawn` (index into the drawn triangles) set up for the walk; false when it occupies
// nothing (blended, degenerate, or outside the grid).
bool setup(uint drawn, out Walk walk) {
    const VisTriangle tri = fetchTriangle(drawn + 1u);
    if (materials[tri.material].alphaMode == ALPHA_BLEND) return false;
    const vec3 n3 = cross(tri.p[1] - tri.p[0], tri.p[2] - tri.p[0]);
    const vec3 a = abs(n3);
    if (max(a.x, max(a.y, a.z)) <= 0.0) return false;
    const bool mirrored = instances[visDrawn[drawn].x].mirrored != 0u;  // its world-space winding flips
    walk.skyFacing = skyFacing(materials[tri.material], mirrored ? -n3 : n3);
    walk.axes = a.z >= a.x && a.z >= a.y ? ivec3(0, 1, 2) : (a.y >= a.x ? ivec3(2, 0, 1) : ivec3(1, 2, 0));
    const ivec3 dims = ivec3(occupancy.grid.dims);
    vec3 lo = vec3(1e30), hi = vec3(-1e30);
    for (int k = 0; k < 3; ++k) {
        const vec3 p = (tri.p[k] - occupancy.grid.origin) / occupancy.grid.voxelSize;
        walk.v[k] = vec3(p[walk.axes.x], p[walk.axes.y], p[walk.axes.z]);
        lo = min(lo, walk.v[k]);
        hi = max(hi, walk.v[k]);
    }
    walk.normal = vec3(n3[walk.axes.x], n3[walk.axes.y], n3[walk.axes.z]);
    const ivec3 gridUvw = ivec3(dims[walk.axes.x], dims[walk.axes.y], dims[walk.axes.z]);
    const ivec3 first = max(ivec3(floor(lo)), ivec3(0)), last = min(ivec3(floor(hi)), gridUvw - 1);
    if (any(greaterThan(first, last))) return false;
    walk.lo = first.xy;
    walk.size = last.xy - first.xy + 1;
    walk.wRange = vec2(lo.z, hi.z);
    return true;
}

// The voxel's bit, and its facing bits where the volume has them and the triangle blocks any quadrant.
void setVoxel(ivec3 uvw, ivec3 axes, uint skyFacing) {
    ivec3 c;
    c[axes.x] = uvw.x;
    c[axes.y] = uvw.y;
    c[axes.z] = uvw.z;
    const uvec3 dims = occupancy.grid.dims;
    const uint index = uint(c.x) + dims.x * (uint(c.y) + dims.y * uint(c.z));
    atomicOr(occupancy.bits[index >> 5u], 1u << (index & 31u));
    if (occupancy.grid.skyFirstWord == 0u || skyFacing == 0u) return;
    const uint shift = (index % OCCUPANCY_SKY_VOXELS_PER_WORD) * OCCUPANCY_SKY_QUADRANTS;
    atomicOr(occupancy.bits[occupancy.grid.skyFirstWord + index / OCCUPANCY_SKY_VOXELS_PER_WORD], skyFacing << shift);
}

// Whether the triangle (voxel units) meets the unit voxel whose lower corner is `corner`: no
// separating axis among the voxel's three, the triangle's normal and the nine cross products of the
// edges with the voxel's axes (Akenine-Moller 2001). Touching counts as meeting.
bool triangleMeetsVoxel(vec3 t0, vec3 t1, vec3 t2, vec3 corner) {
    const vec3 c = corner + 0.5;
    const vec3 v[3] = vec3[3](t0 - c, t1 - c, t2 - c);
    if (any(greaterThan(min(v[0], min(v[1], v[2])), vec3(0.5))) || any(lessThan(max(v[0], max(v[1], v[2])), vec3(-0.5))))
        return false;
    const vec3 n = cross(v[1] - v[0], v[2] - v[0]);
    if (abs(dot(n, v[0])) > 0.5 * (abs(n.x) + abs(n.y) + abs(n.z))) return false;
    for (int e = 0; e < 3; ++e) {
        const vec3 edge = v[(e + 1) % 3] - v[e];
        for (int a = 0; a < 3; ++a) {
            vec3 unit = vec3(0.0);
            unit[a] = 1.0;
            const vec3 axis = cross(unit, edge);
            const float p0 = dot(axis, v[0]), p1 = dot(axis, v[1]), p2 = dot(axis, v[2]);
            const float r = 0.5 * (abs(axis.x) + abs(axis.y) + abs(axis.z));
            if (min(p0, min(p1, p2)) > r || max(p0, max(p1, p2)) < -r) return false;
        }
    }
    return true;
}

// Column `column` (row-major in the walk's box): the voxels of the triangle above its square.
void walkColumn(Walk walk, int column) {
    const ivec2 cell = walk.lo + ivec2(column % walk.size.x, column / walk.size.x);
    const vec2 centre = vec2(cell) + 0.5;
    // The square meets the triangle's projection unless one of its edges separates them.
    const float area = (walk.v[1].x - walk.v[0].x) * (walk.v[2].y - walk.v[0].y) -
                       (walk.v[2].x - walk.v[0].x) * (walk.v[1].y - walk.v[0].y);
    const float side = area >= 0.0 ? 1.0 : -1.0;
    for (int k = 0; k < 3; ++k) {
        const vec2 p = walk.v[k].xy, e = walk.v[(k + 1) % 3].xy - p;
        const vec2 inward = side * vec2(-e.y, e.x);
        if (dot(inward, centre - p) + 0.5 * (abs(inward.x) + abs(inward.y)) < 0.0) return;
    }
    // The plane's w over the square (the normal's w is the largest component: |slope| <= 1 per axis),
    // within the triangle's own extent along w.
    const vec3 n = walk.normal;
    const float w = walk.v[0].z - (n.x * (centre.x - walk.v[0].x) + n.y * (centre.y - walk.v[0].y)) / n.z;
    const float spread = 0.5 * (abs(n.x) + abs(n.y)) / abs(n.z);
    const int gridW = int(occupancy.grid.dims[walk.axes.z]);
    const int w0 = max(int(floor(max(w - spread, walk.wRange.x))), 0);
    const int w1 = min(int(floor(min(w + spread, walk.wRange.y))), gridW - 1);
    for (int k = w0; k <= w1; ++k)
        if (triangleMeetsVoxel(walk.v[0], walk.v[1], walk.v[2], vec3(cell, k))) setVoxel(ivec3(cell, k), walk.axes, walk.skyFacing);
}

void main() {
    if (pc.walkChunks == 1u) {  // one listed chunk per workgroup
        const uvec2 chunk = list.chunks[gl_WorkGroupID.x];
        Walk walk;
        setup(chunk.x, walk);  // true: it was listed
        const int end = min(int(chunk.y) + OCCUPANCY_CHUNK_COLUMNS, walk.size.x * walk.size.y);
        for (int c = int(chunk.y + gl_LocalInvocationIndex); c < end; c += OCCUPANCY_GROUP) walkColumn(walk, c);
        return;
    }
    const uint group = gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x;  // 2D beyond 65535 groups
    const uint drawn = group * OCCUPANCY_GROUP + gl_LocalInvocationIndex;
    Walk walk;
    if (drawn >= pc.triangleCount || !setup(drawn, walk)) return;
    const int columns = walk.size.x * walk.size.y;
    if (columns > OCCUPANCY_SMALL_COLUMNS) {
        const uint count = uint(columns + OCCUPANCY_CHUNK_COLUMNS - 1) / OCCUPANCY_CHUNK_COLUMNS;
        const uint first = atomicAdd(list.args.x, count);
        if (first + count <= pc.chunkCapacity) {
            for (uint k = 0u; k < count; ++k) list.chunks[first + k] = uvec2(drawn, k * OCCUPANCY_CHUNK_COLUMNS);
            return;
        }
        atomicAdd(list.args.x, -count);  // no room: walked here
    }
    for (int c = 0; c < columns; ++c) walkColumn(walk, c);
}
