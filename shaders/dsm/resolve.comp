#version 460
// DSM resolve, one thread per texel of every layer. The build left each list in drawing order, its
// nodes scattered over the pool; this keeps the list's `maxList` nearest nodes, sorted by depth, each
// holding the transmittance behind it, T_k = prod_{j<=k} (1 - alpha_j). Farther nodes (the list's
// tail after sorting) are unlinked and counted.
//
// The sorted nodes are written packed: a workgroup's lists (an 8x8 tile of texels) side by side in
// the pool after the build's nodes, each list in consecutive nodes, so that the link pass and every
// lookup walk memory in order (the lookups of the camera's hair layers walked scattered nodes: most
// of oit.composite on the H100). The texel's first head slot then points at the packed list, its
// second holds the list's length, and the side buffer its depths (one uint per node, the depths
// alone: a binary search touches 4 bytes a step, not a node's 16). When the pool has no room left
// for a tile, its lists are written back in place into their own first nodes instead, with length
// 0 (not packed: a lookup walks them). The build's nodes of a texel are on DSM_CHAINS lists
// (shared/types.h), walked side by side.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "shared/types.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, std430) buffer Heads { uint heads[]; };
layout(set = 0, binding = 1, std430) buffer Nodes { uvec4 nodes[]; };
layout(set = 0, binding = 2, std430) buffer Stats { DsmStats stats; };
layout(set = 0, binding = 3, std430) writeonly buffer Keys { uint keys[]; };  // the side buffer
layout(push_constant) uniform Push { DsmPush pc; };

shared uint groupKept, groupDropped, groupLongest, groupLists, groupPacked;

#define SORT_CAPACITY DSM_MAX_LIST_CAP
#define SORT_CHAINS DSM_CHAINS
vec2 sortEntry(uint n, uvec4 node) { return vec2(uintBitsToFloat(node.x), uintBitsToFloat(node.y)); }  // (depth, alpha)
uint sortTieKey(vec2 e) { return floatBitsToUint(e.y); }
#include "dsm/sort_nearest.glsl"

// The node after n when the texel's chains are read one after the other (chain c holds n).
uint nextInChains(uint n, uint chains[DSM_CHAINS], inout uint c) {
    uint next = nodes[n].z;
    while (next == DSM_NONE && ++c < DSM_CHAINS) next = chains[c];
    return next;
}

// Writes the `count` sorted entries as one list: at `first` onwards (packed), or, with first ==
// DSM_NONE, into the texel's own first nodes (in place, over its chains one after the other).
// Either way the texel's first head slot then holds the list's head, the second its length (0 in
// place: not packed).
void writeList(uint texel, uint chains[DSM_CHAINS], uint count, uint first) {
    float t = 1.0;
    uint c = 0u;
    while (chains[c] == DSM_NONE) ++c;  // a texel with a list has a chain that is not empty
    uint n = first == DSM_NONE ? chains[c] : first;
    heads[texel * DSM_CHAINS] = n;
    heads[texel * DSM_CHAINS + 1u] = first == DSM_NONE ? 0u : count;
    for (uint i = 0; i < count; ++i) {
        uint next = first == DSM_NONE ? nextInChains(n, chains, c) : n + 1;
        t *= 1.0 - clamp(sorted(i).y, 0.0, 1.0);
        nodes[n] = uvec4(floatBitsToUint(sorted(i).x), floatBitsToUint(t), i + 1 < count ? next : DSM_NONE, DSM_NONE);
        if (first != DSM_NONE) keys[n] = floatBitsToUint(sorted(i).x);
        n = next;
    }
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
    uint texel = (id.z * res + id.y) * res + id.x;
    uint chains[DSM_CHAINS];
    bool listed = false;
    [[unroll]] for (int k = 0; k < DSM_CHAINS; ++k) {
        chains[k] = id.x < res && id.y < res ? heads[texel * DSM_CHAINS + k] : DSM_NONE;
        listed = listed || chains[k] != DSM_NONE;
    }
    uint count = 0u, length = 0u;
    if (listed) length = sortNearest(chains, pc.sizes.w, pc.sizes.z, count);  // the pool bounds a list
    // This texel's place among the tile's packed lists, then the tile's place in the pool (one
    // global atomic per tile, on a counter of its own: build.z).
    uint offset = atomicAdd(groupKept, count);
    barrier();
    if (gl_LocalInvocationIndex == 0) {
        uint used = min(stats.build.x, pc.sizes.z);  // the build's nodes
        uint start = groupKept > 0u ? used + atomicAdd(stats.build.z, groupKept) : 0u;
        groupPacked = groupKept > 0u && start + groupKept <= pc.sizes.z ? start : DSM_NONE;
    }
    barrier();
    if (listed) {
        writeList(texel, chains, count, groupPacked == DSM_NONE ? DSM_NONE : groupPacked + offset);
        atomicAdd(groupDropped, length - count);
        atomicMax(groupLongest, length);
        atomicAdd(groupLists, 1u);
    }
    barrier();
    // One global update per workgroup, not per texel.
    if (gl_LocalInvocationIndex == 0 && groupLists > 0u) {
        atomicAdd(stats.lists.x, groupKept);
        atomicAdd(stats.lists.y, groupDropped);
        atomicMax(stats.lists.z, groupLongest);
        atomicAdd(stats.lists.w, groupLists);
    }
}
