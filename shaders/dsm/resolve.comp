#version 460
// DSM resolve, one workgroup per texel with nodes (the work list of dsm.offsets; a fixed grid of
// workgroups strides over it; each zeroes its texel's bucket counts for the next frame): the
// texel's `maxList` nearest nodes sorted by depth, each holding the transmittance behind it,
// T_k = prod_{j<=k} (1 - alpha_j); farther nodes are dropped (dsm.offsets counted them). The
// texel's fragments (consecutive in its run, the build's) go into shared slots, a bitonic network
// sorts them and the nearest `maxList` stay; a list longer than the slots comes in
// batches, and once the cap is full only nodes nearer than the farthest kept take a slot. (One
// thread per texel walking linked lists into a heap kept 50 heap entries per thread in local memory,
// more than a GPU's L1 holds, so the heap's spills dominated the pass; one workgroup per 8x8 tile,
// sorting its texels one after another, made a dense tile the whole pass's critical path.
// docs/techniques/dsm.md.)
//
// The sorted list is written packed at the start of the texel's run's indices, in the pool, and its
// depths in the side buffer at the same indices (one uint per node: a binary search touches 4 bytes
// a step, not a node's 16). The texel's first head slot then points at the list, its second holds
// the list's length. Equal depths are ordered by alpha, so that the same nodes are kept every run.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "dsm/bindings.h"

#define GROUP_SIZE 64
// Shared sort slots: up to DSM_MAX_LIST_CAP kept nodes and the batches that come after them.
#define SORT_SLOTS (2 * DSM_MAX_LIST_CAP)

layout(local_size_x = GROUP_SIZE) in;
layout(set = 0, binding = DSM_RESOLVE_HEADS, std430) buffer Heads { uint heads[]; };
layout(set = 0, binding = DSM_RESOLVE_NODES, std430) buffer Nodes { uvec4 nodes[]; };
layout(set = 0, binding = DSM_RESOLVE_SIDE, std430) writeonly buffer Side { uint side[]; };  // the search keys
layout(set = 0, binding = DSM_RESOLVE_WORK, std430) readonly buffer Work { uvec4 header; uint texels[]; } work;
layout(set = 0, binding = DSM_RESOLVE_RUNS, std430) readonly buffer Runs { uvec2 runs[]; };  // (depth, alpha) bits
layout(set = 0, binding = DSM_RESOLVE_BUCKETS, std430) writeonly buffer Buckets { uint buckets[]; };  // pc.bucketsPerTexel per texel
layout(push_constant) uniform Push { DsmPush pc; };

shared uvec2 slots[SORT_SLOTS];  // (depth bits, alpha bits)
shared uint slotCount;

const uvec2 kPad = uvec2(0x7F800000u, 0xFFFFFFFFu);  // +inf: sorts after every node

// Whether a goes before b: nearer, or as near with a smaller alpha.
bool nearer(uvec2 a, uvec2 b) {
    float da = uintBitsToFloat(a.x), db = uintBitsToFloat(b.x);
    return da < db || (da == db && a.y < b.y);
}

// Sorts slots[0, count) ascending (count a power of two), every thread taking its share of each
// step's pairs; ends with a barrier.
void bitonicSort(uint count) {
    for (uint k = 2u; k <= count; k <<= 1)
        for (uint j = k >> 1; j > 0u; j >>= 1) {
            for (uint p = gl_LocalInvocationIndex; p < count / 2u; p += GROUP_SIZE) {
                uint i = ((p & ~(j - 1u)) << 1) | (p & (j - 1u));
                uvec2 a = slots[i], b = slots[i | j];
                if ((i & k) == 0u ? nearer(b, a) : nearer(a, b)) {
                    slots[i] = b;
                    slots[i | j] = a;
                }
            }
            barrier();
        }
}

// Sorts slots[0, filled) and keeps the `maxList` nearest; returns how many it kept. Ends with a barrier.
uint sortSlots(uint filled, uint maxList) {
    uint size = filled <= 1u ? 1u : 1u << (findMSB(filled - 1u) + 1);
    for (uint s = filled + gl_LocalInvocationIndex; s < size; s += GROUP_SIZE) slots[s] = kPad;
    barrier();
    bitonicSort(size);
    uint kept = min(maxList, filled);
    if (gl_LocalInvocationIndex == 0u) slotCount = kept;
    barrier();
    return kept;
}

// A run of at most GROUP_SIZE nodes, one per invocation: each goes straight to its rank among them
// (the nodes nearer than it, and the equal ones before it), two barriers in place of the network's
// 21 steps of one. Leaves the `maxList` nearest sorted in slots[0, kept); returns kept. Only runs
// of one node an invocation: ranking two nodes an invocation doubles each invocation's comparisons
// and was slower than the network.
uint rankSmallRun(uint run, uint count, uint maxList) {
    const uint i = gl_LocalInvocationIndex, input_ = DSM_MAX_LIST_CAP;  // slots[input_, + count): the run
    uvec2 e = i < count ? runs[run + i] : kPad;
    if (i < count) slots[input_ + i] = e;
    barrier();
    if (i < count) {
        uint rank = 0u;
        for (uint j = 0u; j < count; ++j) {
            uvec2 o = slots[input_ + j];
            rank += nearer(o, e) || (o == e && j < i) ? 1u : 0u;
        }
        if (rank < maxList) slots[rank] = e;  // rank < count <= GROUP_SIZE <= input_
    }
    barrier();
    return min(count, maxList);
}

// Leaves the `maxList` nearest of the `count` nodes at runs[run...] sorted in slots[0, kept). The
// nodes come GROUP_SIZE at a time; once `maxList` are kept, only nodes nearer than the farthest of
// them take a slot, so that a long list's tail (most of it, in dense hair) costs a read and a
// comparison, not a place in the sort.
uint sortNearest(uint run, uint count, uint maxList) {
    if (count <= GROUP_SIZE) return rankSmallRun(run, count, maxList);
    if (gl_LocalInvocationIndex == 0u) slotCount = 0u;
    barrier();
    uint filled = 0u;
    uvec2 farthestKept = kPad;
    for (uint done = 0u; done < count; done += GROUP_SIZE) {
        if (filled + GROUP_SIZE > SORT_SLOTS) {
            filled = sortSlots(filled, maxList);
            farthestKept = filled == maxList ? slots[filled - 1u] : kPad;
        }
        uint i = done + gl_LocalInvocationIndex;
        if (i < count) {
            uvec2 e = runs[run + i];
            if (nearer(e, farthestKept)) slots[atomicAdd(slotCount, 1u)] = e;
        }
        barrier();
        filled = slotCount;
        barrier();  // every thread has read slotCount before sortSlots resets it
    }
    return sortSlots(filled, maxList);
}

// Writes the sorted `count` nodes of slots as the texel's list at `first` onwards. Ends with a barrier.
void writeList(uint texel, uint count, uint first) {
    for (uint k = gl_LocalInvocationIndex; k < count; k += GROUP_SIZE) {
        float t = 1.0;  // the same products, in the same order, as a walk down the list
        for (uint i = 0u; i <= k; ++i) t *= 1.0 - clamp(uintBitsToFloat(slots[i].y), 0.0, 1.0);
        nodes[first + k] = uvec4(slots[k].x, floatBitsToUint(t), k + 1u < count ? first + k + 1u : DSM_NONE, DSM_NONE);
        side[first + k] = slots[k].x;
    }
    if (gl_LocalInvocationIndex == 0u) {
        heads[texel * DSM_HEAD_UINTS] = first;
        heads[texel * DSM_HEAD_UINTS + 1u] = count;
    }
    barrier();
}

void main() {
    const uint perTexel = pc.bucketsPerTexel;
    for (uint w = gl_WorkGroupID.x; w < work.header.x; w += gl_NumWorkGroups.x) {
        uint entry = work.texels[w], texel = entry & ~DSM_WORK_UNLISTED;
        // The build is done with the texel's counts: zeroed for the next frame's (dsm.offsets).
        if (gl_LocalInvocationIndex < perTexel) buckets[texel * perTexel + gl_LocalInvocationIndex] = 0u;
        if (entry != texel) continue;  // counted, but its tile found no room in the pool
        uint count = heads[texel * DSM_HEAD_UINTS], run = heads[texel * DSM_HEAD_UINTS + 1u];
        writeList(texel, sortNearest(run, count, pc.maxList), run);
    }
}
