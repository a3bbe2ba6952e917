#version 460
// DSM scatter, one thread per node the build stored: the node's (depth, alpha) into its texel's run,
// at its bucket's place there (dsm.offsets; none for a bucket behind the list cap's) plus its place
// in the bucket (dsm/dsm_insert.glsl), so that the resolve reads each texel's nodes in consecutive
// memory. A fixed grid strides over the nodes: no indirect dispatch.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(local_size_x = 256) in;
layout(set = 0, binding = 0, std430) readonly buffer Buckets { uint buckets[]; };  // places
layout(set = 0, binding = 1, std430) readonly buffer Nodes { uvec4 nodes[]; };
layout(set = 0, binding = 2, std430) readonly buffer Stats { DsmStats stats; };
layout(set = 0, binding = 3, std430) writeonly buffer Runs { uvec2 runs[]; };
layout(push_constant) uniform Push { DsmPush pc; };

void main() {
    const uint stored = min(stats.build.x, pc.sizes.z);  // nodes written (the pool bounds them)
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint n = gl_GlobalInvocationID.x; n < stored; n += stride) {
        uvec4 node = nodes[n];  // (depth, alpha, texel, bucket and place)
        uint start = buckets[node.z * pc.buckets.x + (node.w >> DSM_BUCKET_SHIFT)];
        if (start != DSM_NONE) runs[start + (node.w & ((1u << DSM_BUCKET_SHIFT) - 1u))] = node.xy;
    }
}
