#version 460
// DSM resolve, one thread per texel of every layer. The build left each list in drawing order; this
// keeps its `maxList` nearest nodes, sorted by depth, each holding the transmittance behind it,
// T_k = prod_{j<=k} (1 - alpha_j). Farther nodes (the list's tail after sorting) are unlinked and
// counted. The sorted values are written back into the list's first nodes, so no allocation is needed.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, std430) readonly buffer Heads { uint heads[]; };
layout(set = 0, binding = 1, std430) buffer Nodes { uvec4 nodes[]; };
layout(set = 0, binding = 2, std430) buffer Stats { DsmStats stats; };
layout(push_constant) uniform Push { DsmPush pc; };

shared uint groupKept, groupDropped, groupLongest, groupLists;

#define SORT_CAPACITY DSM_MAX_LIST_CAP
vec2 sortEntry(uint n) { return vec2(uintBitsToFloat(nodes[n].x), uintBitsToFloat(nodes[n].y)); }  // (depth, alpha)
#include "dsm/sort_nearest.glsl"

void resolveTexel(uint texel) {
    uint head = heads[texel];
    if (head == DSM_NONE) return;
    uint count;
    uint length = sortNearest(head, pc.sizes.w, pc.sizes.z, count);  // the pool bounds a list
    float t = 1.0;
    uint n = head;
    for (uint i = 0; i < count; ++i) {
        uint next = nodes[n].z;
        t *= 1.0 - clamp(sorted[i].y, 0.0, 1.0);
        nodes[n] = uvec4(floatBitsToUint(sorted[i].x), floatBitsToUint(t), i + 1 < count ? next : DSM_NONE, DSM_NONE);
        n = next;
    }
    atomicAdd(groupKept, count);
    atomicAdd(groupDropped, length - count);
    atomicMax(groupLongest, length);
    atomicAdd(groupLists, 1u);
}

void main() {
    if (gl_LocalInvocationIndex == 0) {
        groupKept = 0u;
        groupDropped = 0u;
        groupLongest = 0u;
        groupLists = 0u;
    }
    barrier();
    const uint res = pc.sizes.x;
    uvec3 id = gl_GlobalInvocationID;
    if (id.x < res && id.y < res) resolveTexel((id.z * res + id.y) * res + id.x);
    barrier();
    // One global update per workgroup, not per texel.
    if (gl_LocalInvocationIndex == 0 && groupLists > 0u) {
        atomicAdd(stats.lists.x, groupKept);
        atomicAdd(stats.lists.y, groupDropped);
        atomicMax(stats.lists.z, groupLongest);
        atomicAdd(stats.lists.w, groupLists);
    }
}
