#version 460
// DSM offsets, one thread per texel of every layer, between the build's two steps: the texel keeps
// its depth buckets up to the one that brings its count to the list cap (every fragment behind that
// bucket has the cap's number in front of it: it cannot be kept) and gets a run of as many entries
// (length and start in its heads), each kept bucket a place in it, where the build's second step
// stores those fragments (a bucket left out gets DSM_CULLED: nothing is stored), and a place in the
// work list of the resolve (one workgroup per listed texel). An empty texel gets its final heads
// (DSM_NONE, 0). One 8x8 tile's runs and work are side by side (one global atomic each per tile: one
// per texel, on one counter, would serialise). A tile whose runs do not fit the pool is dropped
// whole and counted (build.z); its texels still get a place in the work list, marked
// DSM_WORK_UNLISTED: the resolve, the last reader of the counts, zeroes every counted texel's buckets
// for the next frame (so that no pass fills the whole buffer). The statistics (fragments, kept,
// dropped beyond the cap, longest, lists) are counted here, once per tile.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "dsm/bindings.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = DSM_OFFSETS_HEADS, std430) writeonly buffer Heads { uint heads[]; };
layout(set = 0, binding = DSM_OFFSETS_STATS, std430) buffer Stats { DsmStats stats; };
layout(set = 0, binding = DSM_OFFSETS_WORK, std430) buffer Work { uvec4 header; uint texels[]; } work;
layout(set = 0, binding = DSM_OFFSETS_BUCKETS, std430) buffer Buckets { uint buckets[]; };  // counts in, places out
layout(push_constant) uniform Push { DsmPush pc; };

#define CELL_BUCKETS DSM_BUCKETS
#include "dsm/depth_buckets.glsl"

shared uint groupEntries, groupAll, groupKept, groupLongest, groupLists, groupRun, groupWork;

void main() {
    if (gl_LocalInvocationIndex == 0) groupEntries = groupAll = groupKept = groupLongest = groupLists = 0u;
    barrier();
    const uint res = pc.resolution, perTexel = pc.bucketsPerTexel, maxList = pc.maxList;
    uvec3 id = gl_GlobalInvocationID;
    bool inside = id.x < res && id.y < res;
    uint texel = (id.z * res + id.y) * res + id.x;
    uint counts[CELL_BUCKETS];
    readBucketCounts(texel, perTexel, inside, counts);
    uint count, entries;  // all the texel's fragments; those in the buckets it keeps
    uint kept = bucketsKept(counts, perTexel, maxList, entries, count);
    uint offset = 0u, place = 0u;
    if (count > 0u) {
        offset = atomicAdd(groupEntries, entries);
        place = atomicAdd(groupLists, 1u);
        atomicAdd(groupAll, count);
        atomicAdd(groupKept, min(count, maxList));
        atomicMax(groupLongest, count);
    }
    barrier();
    if (gl_LocalInvocationIndex == 0 && groupLists > 0u) {
        atomicAdd(stats.fragments, groupAll);
        groupRun = atomicAdd(stats.runEntries, groupEntries);
        groupWork = atomicAdd(work.header.x, groupLists);
        if (groupRun + groupEntries > pc.nodeCapacity) {  // no room: the tile is dropped
            atomicAdd(stats.runEntries, 0u - groupEntries);
            atomicAdd(stats.overflow, groupAll);
            groupRun = DSM_NONE;
        } else {
            atomicAdd(stats.kept, groupKept);
            atomicAdd(stats.beyondMaxList, groupAll - groupKept);
            atomicMax(stats.longest, groupLongest);
            atomicAdd(stats.lists, groupLists);
        }
    }
    barrier();
    bool listed = count > 0u && groupRun != DSM_NONE;
    uint start = groupRun + offset;
    if (count > 0u) {
        writeBucketPlaces(texel, perTexel, counts, kept, start, listed);
        work.texels[groupWork + place] = listed ? texel : texel | DSM_WORK_UNLISTED;
    }
    if (listed) {
        heads[texel * DSM_HEAD_UINTS] = entries;
        heads[texel * DSM_HEAD_UINTS + 1u] = start;
    } else if (inside) {
        heads[texel * DSM_HEAD_UINTS] = DSM_NONE;
        heads[texel * DSM_HEAD_UINTS + 1u] = 0u;
    }
}
