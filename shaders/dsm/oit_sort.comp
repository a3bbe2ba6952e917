#version 460
// Camera translucency, first of three passes (src/dsm/translucency.h), one thread per pixel: the
// pixel's OIT_MAX_LIST nearest fragments (of its run, oit.offsets) in depth order,
// appended to the kept-layer list that oit_shade.comp lights one layer per thread, and the pixel's
// header for oit_blend.comp: heads[4 p] = its first entry, + 1 = how many, + 2 = the log-transmittance
// of all its fragments (summed by the build's first step), + 3 = how many fragments it has (stored or
// in the buckets left out). A pixel without stored fragments keeps DSM_NONE in its first head.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#include "shared/types.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, std430) buffer Heads { uint heads[]; };
layout(set = 0, binding = 1, std430) readonly buffer Nodes { uvec4 nodes[]; };
layout(set = 0, binding = 2, std430) readonly buffer Normals { uint normals[]; };
layout(set = 0, binding = 3, std430) buffer Stats { OitStats stats; };
layout(set = 0, binding = 4, std430) buffer Layers { uvec4 header; uvec2 entries[]; } layers;  // (node, pixel)
layout(set = 0, binding = 5, std430) readonly buffer Tails { uint64_t tails[]; };  // sum of -log(1 - alpha)
layout(push_constant) uniform Push { OitPush pc; };

#define SORT_CAPACITY OIT_MAX_LIST
#define SORT_SHARED_GROUP 64
vec2 sortEntry(uint n, uvec4 node) { return vec2(uintBitsToFloat(node.x), uintBitsToFloat(n)); }  // (depth, node)
// Equal depths (read only then): by the fragment's tangent or normal, colour and alpha.
uint sortTieKey(vec2 e) {
    uint n = floatBitsToUint(e.y);
    return normals[n] ^ (nodes[n].w * 0x9E3779B9u) ^ (nodes[n].y * 0x85EBCA6Bu);
}
#include "dsm/sort_nearest.glsl"

shared uint groupKept, groupDropped, groupLongest, groupStart;

void main() {
    if (gl_LocalInvocationIndex == 0) groupKept = groupDropped = groupLongest = 0u;
    barrier();
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    bool inside = all(lessThan(pixel, ivec2(pc.sizes.xy)));
    uint base = (uint(pixel.y) * pc.sizes.x + uint(pixel.x)) * OIT_HEADER_UINTS;
    uint start = inside ? heads[base] : DSM_NONE;  // oit.offsets' header: the run, its nodes, all fragments
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
        heads[base + 2u] = floatBitsToUint(-float(tails[base / OIT_HEADER_UINTS]) / OIT_LOG_SCALE);
    }
    if (gl_LocalInvocationIndex == 0 && (groupKept | groupDropped) != 0u) {
        atomicAdd(stats.counts.y, groupKept);
        atomicAdd(stats.counts.z, groupDropped);
        atomicMax(stats.counts.w, groupLongest);
    }
}
