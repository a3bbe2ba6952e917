#version 460
// Tile lists of the compute rasterizer (src/raster): the bins' counts into list offsets, an exclusive
// prefix sum in one workgroup (each thread sums a run of bins, the runs' sums are scanned in shared
// memory, then each thread writes its run's offsets). A few thousand to a few hundred thousand bins.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(local_size_x = RASTER_SCAN_GROUP) in;
layout(set = 0, binding = 0, std430) buffer TileBins { uvec4 tileBins[]; };  // x count, y offset
layout(push_constant) uniform Push { uvec4 bins; };                            // x = number of bins

shared uint runSums[RASTER_SCAN_GROUP];

void main() {
    const uint n = bins.x, per = (n + RASTER_SCAN_GROUP - 1u) / RASTER_SCAN_GROUP;
    const uint begin = min(gl_LocalInvocationIndex * per, n), end = min(begin + per, n);
    uint sum = 0u;
    for (uint i = begin; i < end; ++i) sum += tileBins[i].x;
    runSums[gl_LocalInvocationIndex] = sum;
    barrier();
    for (uint d = 1u; d < RASTER_SCAN_GROUP; d <<= 1) {  // inclusive scan (Hillis-Steele)
        const uint v = gl_LocalInvocationIndex >= d ? runSums[gl_LocalInvocationIndex - d] : 0u;
        barrier();
        runSums[gl_LocalInvocationIndex] += v;
        barrier();
    }
    uint offset = runSums[gl_LocalInvocationIndex] - sum;
    for (uint i = begin; i < end; ++i) {
        tileBins[i].y = offset;
        offset += tileBins[i].x;
    }
}
