#version 460
// DSM scatter, one thread per node the build stored: the node's index into its texel's run in the
// side buffer, at its place among the texel's nodes (both from the build, dsm/dsm_insert.glsl; the
// run's start from dsm.offsets). A fixed grid strides over the nodes: no indirect dispatch.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(local_size_x = 256) in;
layout(set = 0, binding = 0, std430) readonly buffer Heads { uint heads[]; };
layout(set = 0, binding = 1, std430) readonly buffer Nodes { uvec4 nodes[]; };
layout(set = 0, binding = 2, std430) readonly buffer Stats { DsmStats stats; };
layout(set = 0, binding = 3, std430) writeonly buffer Runs { uint runs[]; };  // the side buffer
layout(push_constant) uniform Push { DsmPush pc; };

void main() {
    const uint stored = min(stats.build.x, pc.sizes.z);  // nodes written (the pool bounds them)
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint n = gl_GlobalInvocationID.x; n < stored; n += stride) {
        uvec2 texelAndPlace = nodes[n].zw;
        runs[heads[texelAndPlace.x * DSM_HEAD_UINTS + 1u] + texelAndPlace.y] = n;
    }
}
