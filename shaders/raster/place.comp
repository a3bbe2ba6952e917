#version 460
// Tile lists of the compute rasterizer (src/raster): each tile's list gets its place in the list
// buffer, one thread per tile bin. The lists need not be in tile order, so each subgroup sums its
// tiles' counts and takes one range with one atomic; its tiles take consecutive offsets inside it
// (a workgroup-wide prefix sum over 16384 bins runs on one workgroup, a serial step of the frame).
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "shared/types.h"

layout(local_size_x = RASTER_PLACE_GROUP) in;
#include "raster/bindings.h"
layout(set = 0, binding = RASTER_PLACE_TILE_BINS, std430) buffer TileBins { uvec4 tileBins[]; };  // x count, y offset
layout(set = 0, binding = RASTER_PLACE_COUNTERS, std430) buffer Counters { RasterCounters counters; };  // counts the entries placed
layout(push_constant) uniform Push { uvec4 bins; };                                // x = number of bins

void main() {
    const uint bin = gl_GlobalInvocationID.x;
    const uint count = bin < bins.x ? tileBins[bin].x : 0u;
    const uint before = subgroupExclusiveAdd(count), total = subgroupAdd(count);
    uint base = 0u;
    if (subgroupElect() && total > 0u) base = atomicAdd(counters.placed, total);
    base = subgroupBroadcastFirst(base);
    if (count > 0u) tileBins[bin].y = base + before;
}
