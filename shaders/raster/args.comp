#version 460
// Indirect dispatch arguments from the setup pass's counts (src/raster): the scatter pass, one thread
// per tile entry, and the bin pass, one workgroup per large-triangle record; at most 65535 workgroups
// each (they stride over the rest).
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(local_size_x = 1) in;
layout(set = 0, binding = 0, std430) readonly buffer Counters { RasterCounters counters; };
layout(set = 0, binding = 1, std430) writeonly buffer Args { uvec4 dispatchArgs[2]; };
layout(push_constant) uniform Push { RasterPush push; };

void main() {
    const uint entries = min(counters.counts.y, push.capacity.y);
    dispatchArgs[0] = uvec4(min((entries + RASTER_SCATTER_GROUP - 1u) / RASTER_SCATTER_GROUP, 65535u), 1u, 1u, 0u);
    dispatchArgs[1] = uvec4(min(min(counters.counts.x, push.capacity.x), 65535u), 1u, 1u, 0u);
}
