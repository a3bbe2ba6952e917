#version 460
// DSM offsets, one thread per texel of every layer, after the build counted each texel's nodes:
// each texel with nodes gets a run of as many uints in the side buffer (its start in its second head
// slot), where dsm.scatter writes its nodes' indices, a place in the work list of the resolve (one
// workgroup per listed texel) and the place of its sorted list in the pool (the resolve's packed
// lists, after the build's nodes; DSM_NONE when the pool has no room left for the tile's: then the
// resolve writes them in place). An empty texel gets its final heads (DSM_NONE, 0). One 8x8 tile's
// runs, work and lists are side by side (one global atomic each per tile: one per texel, on one
// counter, would serialise). The side buffer's first `build.x` uints are free until the resolve has
// read them (the packed lists' keys go after the build's nodes). The list statistics (kept, dropped
// beyond the cap, longest, lists) are counted here, once per tile.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, std430) buffer Heads { uint heads[]; };
layout(set = 0, binding = 1, std430) buffer Stats { DsmStats stats; };
layout(set = 0, binding = 2, std430) buffer Work { uvec4 header; uvec2 lists[]; } work;  // (texel, first)
layout(push_constant) uniform Push { DsmPush pc; };

shared uint groupNodes, groupKept, groupLongest, groupLists, groupRuns, groupWork, groupPacked;

void main() {
    if (gl_LocalInvocationIndex == 0) groupNodes = groupKept = groupLongest = groupLists = 0u;
    barrier();
    const uint res = pc.sizes.x;
    uvec3 id = gl_GlobalInvocationID;
    bool inside = id.x < res && id.y < res;
    uint texel = (id.z * res + id.y) * res + id.x;
    uint count = inside ? heads[texel * DSM_HEAD_UINTS] : 0u;
    uint offset = 0u, place = 0u, keptOffset = 0u;
    if (count > 0u) {
        offset = atomicAdd(groupNodes, count);
        place = atomicAdd(groupLists, 1u);
        keptOffset = atomicAdd(groupKept, min(count, pc.sizes.w));
        atomicMax(groupLongest, count);
    }
    barrier();
    if (gl_LocalInvocationIndex == 0 && groupLists > 0u) {
        groupRuns = atomicAdd(stats.build.w, groupNodes);
        groupWork = atomicAdd(work.header.x, groupLists);
        uint start = min(stats.build.x, pc.sizes.z) + atomicAdd(stats.build.z, groupKept);
        groupPacked = start + groupKept <= pc.sizes.z ? start : DSM_NONE;
        atomicAdd(stats.lists.x, groupKept);
        atomicAdd(stats.lists.y, groupNodes - groupKept);
        atomicMax(stats.lists.z, groupLongest);
        atomicAdd(stats.lists.w, groupLists);
    }
    barrier();
    if (count > 0u) {
        heads[texel * DSM_HEAD_UINTS + 1u] = groupRuns + offset;
        work.lists[groupWork + place] = uvec2(texel, groupPacked == DSM_NONE ? DSM_NONE : groupPacked + keptOffset);
    } else if (inside) {
        heads[texel * DSM_HEAD_UINTS] = DSM_NONE;
        heads[texel * DSM_HEAD_UINTS + 1u] = 0u;
    }
}
