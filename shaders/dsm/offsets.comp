#version 460
// DSM offsets, one thread per texel of every layer, after the build counted each texel's nodes per
// depth bucket: the texel keeps its buckets up to the one that brings its count to the list cap
// (every node behind that bucket has the cap's number in front of it: it cannot be kept) and gets a
// run of as many entries (length and start in its heads), each kept bucket a place in it (over the
// bucket's count; DSM_NONE for a bucket left out), where dsm.scatter writes those nodes' (depth,
// alpha) and the resolve then the sorted list (in the pool and the side buffer, at the same indices),
// and a place in the work list of the resolve (one workgroup per listed texel). An empty texel gets
// its final heads (DSM_NONE, 0). One 8x8 tile's runs and work are side by side (one global atomic
// each per tile: one per texel, on one counter, would serialise). The list statistics (kept,
// dropped beyond the cap, longest, lists) are counted here, once per tile.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, std430) writeonly buffer Heads { uint heads[]; };
layout(set = 0, binding = 1, std430) buffer Stats { DsmStats stats; };
layout(set = 0, binding = 2, std430) buffer Work { uvec4 header; uint texels[]; } work;
layout(set = 0, binding = 3, std430) buffer Buckets { uint buckets[]; };  // counts in, places out
layout(push_constant) uniform Push { DsmPush pc; };

shared uint groupNodes, groupAll, groupKept, groupLongest, groupLists, groupRuns, groupWork;  // groupNodes: run entries

void main() {
    if (gl_LocalInvocationIndex == 0) groupNodes = groupKept = groupAll = groupLongest = groupLists = 0u;
    barrier();
    const uint res = pc.sizes.x, perTexel = pc.buckets.x, maxList = pc.sizes.w;
    uvec3 id = gl_GlobalInvocationID;
    bool inside = id.x < res && id.y < res;
    uint texel = (id.z * res + id.y) * res + id.x;
    uint counts[DSM_MAX_BUCKETS];
    uint count = 0u, read = 0u;  // all the texel's nodes; those in the buckets it keeps
    for (uint b = 0u; b < perTexel; ++b) {
        counts[b] = inside ? buckets[texel * perTexel + b] : 0u;
        count += counts[b];
        if (read < maxList) read += counts[b];
    }
    uint offset = 0u, place = 0u;
    if (count > 0u) {
        offset = atomicAdd(groupNodes, read);
        place = atomicAdd(groupLists, 1u);
        atomicAdd(groupKept, min(count, maxList));
        atomicAdd(groupAll, count);
        atomicMax(groupLongest, count);
    }
    barrier();
    if (gl_LocalInvocationIndex == 0 && groupLists > 0u) {
        groupRuns = atomicAdd(stats.build.w, groupNodes);
        groupWork = atomicAdd(work.header.x, groupLists);
        atomicAdd(stats.lists.x, groupKept);
        atomicAdd(stats.lists.y, groupAll - groupKept);
        atomicMax(stats.lists.z, groupLongest);
        atomicAdd(stats.lists.w, groupLists);
    }
    barrier();
    if (count > 0u) {
        uint start = groupRuns + offset, at = start;
        for (uint b = 0u; b < perTexel; ++b) {
            buckets[texel * perTexel + b] = at < start + read ? at : DSM_NONE;
            at += counts[b];
        }
        heads[texel * DSM_HEAD_UINTS] = read;
        heads[texel * DSM_HEAD_UINTS + 1u] = start;
        work.texels[groupWork + place] = texel;
    } else if (inside) {
        heads[texel * DSM_HEAD_UINTS] = DSM_NONE;
        heads[texel * DSM_HEAD_UINTS + 1u] = 0u;
    }
}
