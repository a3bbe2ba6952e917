#version 460
// Fine rasterization of large triangles (src/raster): one workgroup per (triangle, tile) entry of the
// setup pass's bins, its threads over the pixels of the tile that the triangle's box covers (a box
// corner in a tile is often a few rows: threads over the whole tile idled). The workgroups stride over
// the entries, so the dispatch never exceeds the device's group-count limit.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "raster/raster.glsl"

layout(local_size_x = RASTER_TILE_GROUP) in;

layout(push_constant) uniform Push { RasterPush push; };

void main() {
    const int res = int(push.target.x), bits = int(push.target.y);
    const uint entries = min(counters.counts.y, push.capacity.y);
    for (uint k = gl_WorkGroupID.x; k < entries; k += gl_NumWorkGroups.x) {
        const uvec2 entry = tileEntries[k];
        if (entry.x == RASTER_NO_RECORD) continue;  // rasterized by its setup thread
        const RasterTriangle t = records[entry.x];
        const Edges e = edgesOf(t, bits, res);
        const ivec4 r = tileRect(ivec2(entry.y & 0xFFFFu, entry.y >> 16), e.bbox);
        if (r.x > r.z || r.y > r.w) continue;
        const int width = r.z - r.x + 1, pixels = width * (r.w - r.y + 1);
        for (int i = int(gl_LocalInvocationIndex); i < pixels; i += RASTER_TILE_GROUP) {
            const ivec2 p = r.xy + ivec2(i % width, i / width);
            if (covers(e, p, bits)) shadeSample(t, p, res);
        }
    }
}
