#version 460
// Indirect dispatch arguments from the setup pass's counts (src/raster): the scatter pass, one thread
// per tile entry, the bin pass, one workgroup per large-triangle record, and the overflow pass's two
// queues, one workgroup per queued pair and part; at most 65535 workgroups along x (they stride).
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "raster/overflow_limits.glsl"

layout(local_size_x = 1) in;
#include "raster/bindings.h"
layout(set = 0, binding = RASTER_ARGS_COUNTERS, std430) readonly buffer Counters { RasterCounters counters; uvec4 work; uvec4 queues; };
layout(set = 0, binding = RASTER_ARGS_DISPATCH, std430) writeonly buffer Args { uvec4 dispatchArgs[4]; };
layout(set = 0, binding = RASTER_ARGS_OVERFLOW_PAIRS, std430) readonly buffer OverflowPairs { uvec2 overflowPairs[]; };
layout(push_constant) uniform Push { RasterPush push; };

void main() {
    const uint entries = min(counters.tileEntries, push.entryCapacity);
    dispatchArgs[0] = uvec4(min((entries + RASTER_SCATTER_GROUP - 1u) / RASTER_SCATTER_GROUP, 65535u), 1u, 1u, 0u);
    dispatchArgs[1] = uvec4(min(min(counters.records, push.recordCapacity), 65535u), 1u, 1u, 0u);
    // The overflow queues (raster/overflow.comp): medium, one part; huge, parts for its largest box.
    const uint capacity = uint(overflowPairs.length()) / 2u;
    const uint parts = max((work.w + RASTER_OVERFLOW_TILES - 1u) / RASTER_OVERFLOW_TILES, 2u);
    dispatchArgs[2] = uvec4(min(min(queues.x, capacity), 65535u), 1u, 1u, 0u);
    dispatchArgs[3] = uvec4(min(min(queues.y, capacity), 65535u), parts, 1u, 0u);
}
