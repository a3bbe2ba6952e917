#version 460
// Camera translucency, first of three passes (src/dsm/translucency.h), one thread per pixel: the
// pixel's OIT_MAX_LIST nearest fragments (of its run, oit.offsets) in depth order,
// appended to the kept-layer list that oit_shade.comp lights one layer per thread, and the pixel's
// header for oit_blend.comp: heads[4 p] = its first entry, + 1 = how many, + 2 = the log-transmittance
// of all its fragments (summed by the build's first step), + 3 = how many fragments it has (stored or
// in the buckets left out). A pixel without stored fragments keeps DSM_NONE in its first head.
// The build's last reader of the pixel's bucket counts and sum: a pixel with fragments (sum not 0)
// zeroes them for the next frame's count, so that only pixels with translucency are cleared (a small
// part of the image) instead of filling the whole buffers every frame.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#include "shared/types.h"
#include "dsm/bindings.h"

#define GROUP_SIZE 64
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = OIT_SORT_HEADS, std430) buffer Heads { uint heads[]; };
layout(set = 0, binding = OIT_SORT_NODES, std430) readonly buffer Nodes { uvec4 nodes[]; };
layout(set = 0, binding = OIT_SORT_NORMALS, std430) readonly buffer Normals { uint normals[]; };
layout(set = 0, binding = OIT_SORT_STATS, std430) buffer Stats { OitStats stats; };
layout(set = 0, binding = OIT_SORT_LAYERS, std430) buffer Layers { uvec4 header; uvec2 entries[]; } layers;  // (node, pixel)
layout(set = 0, binding = OIT_SORT_TAILS, std430) buffer Tails { uint64_t tails[]; };  // sum of -log(1 - alpha)
layout(set = 0, binding = OIT_SORT_BUCKETS, std430) writeonly buffer Buckets { uint buckets[]; };  // per pixel, pc.bucketsPerPixel
layout(push_constant) uniform Push { OitPush pc; };

// (depth, node)
vec2 sortEntry(uint n, uvec4 node) { return vec2(uintBitsToFloat(node.x), uintBitsToFloat(n)); }
// Equal depths (read only then): by the fragment's tangent or normal, colour and alpha, not by where
// the build's atomics happened to put them, so that the result does not change from run to run
// (strands' consecutive segments meet at a point of equal depth: ties are common at the cap).
uint sortTieKey(vec2 e) {
    uint n = floatBitsToUint(e.y);
    return normals[n] ^ (nodes[n].w * 0x9E3779B9u) ^ (nodes[n].y * 0x85EBCA6Bu);
}

#define SORT_BATCH 4  // nodes read before any is sorted: their reads in flight together

// The heap, entry k read and written as sorted(k) (after sortNearest: ascending depth), in shared
// memory, entry k of invocation i at k * GROUP_SIZE + i (consecutive invocations in consecutive
// banks). In shared memory because a local array of this size spills out of the registers to L2.
shared vec2 sortHeap[OIT_MAX_LIST * GROUP_SIZE];
#define sorted(k) sortHeap[(k) * GROUP_SIZE + gl_LocalInvocationIndex]

// Whether a lies farther than b (depth, then the tie key).
bool sortFarther(vec2 a, vec2 b) { return a.x > b.x || (a.x == b.x && sortTieKey(a) > sortTieKey(b)); }

// While the run is read, `sorted` is a max-heap of the kept entries (the farthest at the root): an
// entry costs O(log maxCount) moves, where an insertion into a sorted array cost O(maxCount). This
// restores the heap below entry i, of `count` entries.
void heapSiftDown(uint i, uint count) {
    vec2 e = sorted(i);
    for (;;) {
        uint c = 2u * i + 1u;
        if (c >= count) break;
        if (c + 1u < count && sortFarther(sorted(c + 1u), sorted(c))) ++c;
        if (!sortFarther(sorted(c), e)) break;
        sorted(i) = sorted(c);
        i = c;
    }
    sorted(i) = e;
}

// Adds entry e to the heap of `count` entries, which keeps the `maxCount` nearest.
void heapPush(vec2 e, uint maxCount, inout uint count) {
    if (count < maxCount) {  // sift the new entry up from the end
        uint i = count++;
        for (; i > 0u && sortFarther(e, sorted((i - 1u) / 2u)); i = (i - 1u) / 2u) sorted(i) = sorted((i - 1u) / 2u);
        sorted(i) = e;
    } else if (sortFarther(sorted(0), e)) {  // nearer than the farthest kept: it takes the root's place
        sorted(0) = e;
        heapSiftDown(0u, count);
    }
}

// Keeps the `maxCount` (<= OIT_MAX_LIST) nearest of the `length` nodes at `start`, sorted ascending;
// `count` receives how many were kept.
void sortNearest(uint start, uint length, uint maxCount, out uint count) {
    count = 0;
    for (uint i = 0; i < length; i += SORT_BATCH) {
        uvec4 node[SORT_BATCH];
        [[unroll]] for (uint k = 0; k < SORT_BATCH; ++k)
            if (i + k < length) node[k] = nodes[start + i + k];
        [[unroll]] for (uint k = 0; k < SORT_BATCH; ++k)
            if (i + k < length) heapPush(sortEntry(start + i + k, node[k]), maxCount, count);
    }
    // Heap sort: the farthest to the end, one by one.
    for (uint end = count; end > 1u; --end) {
        vec2 farthest = sorted(0);
        sorted(0) = sorted(end - 1u);
        sorted(end - 1u) = farthest;
        heapSiftDown(0u, end - 1u);
    }
}

shared uint groupKept, groupDropped, groupLongest, groupStart;

void main() {
    if (gl_LocalInvocationIndex == 0) groupKept = groupDropped = groupLongest = 0u;
    barrier();
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    bool inside = all(lessThan(pixel, ivec2(pc.width, pc.height)));
    uint p = uint(pixel.y) * pc.width + uint(pixel.x), base = p * OIT_HEADER_UINTS;
    uint64_t tail = inside ? tails[p] : 0ul;
    if (tail != 0ul) {  // this frame's counts read for the last time: zero for the next frame
        tails[p] = 0ul;
        for (uint b = 0u; b < pc.bucketsPerPixel; ++b) buckets[p * pc.bucketsPerPixel + b] = 0u;
    }
    uint start = tail != 0ul ? heads[base] : DSM_NONE;  // oit.offsets' header: the run, its nodes, all fragments
    bool listed = start != DSM_NONE;
    uint count = 0u, length = listed ? heads[base + 3u] : 0u;
    if (listed) sortNearest(start, heads[base + 1u], OIT_MAX_LIST, count);
    // This pixel's place among the workgroup's entries, then the workgroup's in the list (one
    // global atomic per workgroup).
    uint offset = atomicAdd(groupKept, count);
    if (listed) {
        atomicAdd(groupDropped, length - count);
        atomicMax(groupLongest, length);
    }
    barrier();
    if (gl_LocalInvocationIndex == 0) groupStart = groupKept > 0u ? atomicAdd(layers.header.x, groupKept) : 0u;
    barrier();
    if (listed) {
        uint first = groupStart + offset;
        for (uint i = 0; i < count; ++i)
            layers.entries[first + i] = uvec2(floatBitsToUint(sorted(i).y), uint(pixel.y) << 16 | uint(pixel.x));
        heads[base] = first;
        heads[base + 1u] = count;
        heads[base + 2u] = floatBitsToUint(-float(tail) / OIT_LOG_SCALE);
    }
    if (gl_LocalInvocationIndex == 0 && (groupKept | groupDropped) != 0u) {
        atomicAdd(stats.kept, groupKept);
        atomicAdd(stats.beyondMaxList, groupDropped);
        atomicMax(stats.longest, groupLongest);
    }
}
