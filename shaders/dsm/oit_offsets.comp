#version 460
// Camera translucency, between the build's two steps (src/dsm/translucency.h), one thread per pixel:
// the pixel keeps its depth buckets up to the one whose count reaches OIT_MAX_LIST
// (dsm/depth_buckets.glsl) and gets a run of as many nodes in the pool, each kept bucket its place
// in it (a bucket left out gets DSM_CULLED: the second step stores nothing of it). An 8x8 tile's runs
// are side by side (one atomic per tile); a tile whose runs do not fit the pool is dropped whole and
// counted. The pixel's header for oit.sort: heads[4 p] = run start, + 1 = nodes in it, + 3 = all its
// fragments (DSM_NONE in the first when it has none). A pixel whose sum of -log(1 - alpha) is 0 has
// no fragment (each adds at least 1, dsm/oit_insert.glsl): its counts are not read, which spares
// the reads of most pixels, since hair covers a small part of the image.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#include "shared/types.h"
#include "dsm/bindings.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = OIT_OFFSETS_BUCKETS, std430) buffer Buckets { uint buckets[]; };  // counts in, places out
layout(set = 0, binding = OIT_OFFSETS_STATS, std430) buffer Stats { OitStats stats; };
layout(set = 0, binding = OIT_OFFSETS_HEADS, std430) writeonly buffer Heads { uint heads[]; };
layout(set = 0, binding = OIT_OFFSETS_TAILS, std430) readonly buffer Tails { uint64_t tails[]; };  // per pixel (oit.count)
layout(push_constant) uniform Push { OitPush pc; };

#define CELL_BUCKETS OIT_BUCKETS
#include "dsm/depth_buckets.glsl"

shared uint groupAll, groupEntries, groupRun;

void main() {
    if (gl_LocalInvocationIndex == 0) groupAll = groupEntries = 0u;
    barrier();
    uvec2 pixel = gl_GlobalInvocationID.xy;
    const uint perPixel = pc.bucketsPerPixel, p = pixel.y * pc.width + pixel.x;
    const bool inside = all(lessThan(pixel, uvec2(pc.width, pc.height)));
    uint counts[CELL_BUCKETS];
    readBucketCounts(p, perPixel, inside && tails[p] != 0ul, counts);
    uint entries, count;
    uint kept = bucketsKept(counts, perPixel, OIT_MAX_LIST, entries, count);
    uint offset = 0u;
    if (count > 0u) {
        offset = atomicAdd(groupEntries, entries);
        atomicAdd(groupAll, count);
    }
    barrier();
    if (gl_LocalInvocationIndex == 0 && groupAll > 0u) {
        atomicAdd(stats.fragments, groupAll);
        atomicAdd(stats.leftOut, groupAll - groupEntries);
        groupRun = atomicAdd(stats.runEntries, groupEntries);
        if (groupRun + groupEntries > pc.nodeCapacity) {  // no room: the tile is dropped
            atomicAdd(stats.runEntries, 0u - groupEntries);
            atomicAdd(stats.overflow, groupAll);
            groupRun = DSM_NONE;
        }
    }
    barrier();
    if (!inside) return;
    bool listed = count > 0u && groupRun != DSM_NONE;
    if (count > 0u) writeBucketPlaces(p, perPixel, counts, kept, groupRun + offset, listed);
    heads[p * OIT_HEADER_UINTS] = listed ? groupRun + offset : DSM_NONE;
    heads[p * OIT_HEADER_UINTS + 1u] = listed ? entries : 0u;
    heads[p * OIT_HEADER_UINTS + 3u] = count;
}
