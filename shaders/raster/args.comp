#version 460
// Indirect dispatch arguments of the tile pass from the setup pass's entry count (src/raster):
// one workgroup per entry, at most 65535 (the workgroups stride over the rest).
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(local_size_x = 1) in;
layout(set = 0, binding = 0, std430) readonly buffer Counters { RasterCounters counters; };
layout(set = 0, binding = 1, std430) writeonly buffer Args { uvec4 dispatchArgs; };
layout(push_constant) uniform Push { RasterPush push; };

void main() {
    const uint entries = min(counters.counts.y, push.capacity.y);
    dispatchArgs = uvec4(min(entries, 65535u), 1u, 1u, 0u);
}
