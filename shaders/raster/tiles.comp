#version 460
// Fine rasterization of large triangles (src/raster): one workgroup per (triangle, tile) entry of the
// setup pass's bins, one thread per RASTER_TILE_SIZE^2 / RASTER_TILE_GROUP pixels of the tile (threads
// over only the pixels of the triangle's box in the tile measured 6% slower on the H100: a division per
// pixel, rows no longer aligned to the tile). The workgroups stride over the entries, so the dispatch
// never exceeds the device's group-count limit.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "raster/raster.glsl"

layout(local_size_x = RASTER_TILE_GROUP) in;

layout(push_constant) uniform Push { RasterPush push; };

const int kRowsPerPass = RASTER_TILE_GROUP / RASTER_TILE_SIZE;

void main() {
    const ivec2 size = ivec2(push.target.x, push.capacity.w);
    const int bits = int(push.target.y);
    const uint entries = min(counters.counts.y, push.capacity.y);
    const ivec2 lane = ivec2(int(gl_LocalInvocationIndex) % RASTER_TILE_SIZE,
                             int(gl_LocalInvocationIndex) / RASTER_TILE_SIZE);
    for (uint k = gl_WorkGroupID.x; k < entries; k += gl_NumWorkGroups.x) {
        const uvec2 entry = tileEntries[k];
        if (entry.x == RASTER_NO_RECORD) continue;  // rasterized by its setup thread
        const RasterTriangle t = records[entry.x];
        const Edges e = edgesOf(t, bits, size);
        const ivec2 tile = ivec2(entry.y & 0xFFFFu, entry.y >> 16) * RASTER_TILE_SIZE;
        for (int row = 0; row < RASTER_TILE_SIZE; row += kRowsPerPass) {
            const ivec2 p = tile + lane + ivec2(0, row);
            if (any(lessThan(p, e.bbox.xy)) || any(greaterThan(p, e.bbox.zw))) continue;
            if (covers(e, p, bits)) shadeSample(t, p, size);
        }
    }
}
