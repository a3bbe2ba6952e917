#version 460
// Binning of large triangles (src/raster): one workgroup per record, its threads over the tiles of the
// triangle's box (the entries the setup pass reserved): an entry names the record where no edge
// excludes the tile, else RASTER_NO_RECORD, and counts it in the tile's bin. The coarse stage of
// Laine & Karras (2011), in parallel per triangle.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "raster/raster.glsl"

layout(local_size_x = RASTER_BIN_GROUP) in;

layout(push_constant) uniform Push { RasterPush push; };

void main() {
    const ivec2 size = ivec2(push.width, push.height);
    const int bits = int(push.subpixelBits);
    const uint count = min(counters.records, push.recordCapacity);
    for (uint r = gl_WorkGroupID.x; r < count; r += gl_NumWorkGroups.x) {
        const RasterTriangle t = records[r];
        if (t.firstEntry == RASTER_NO_ENTRY) continue;  // the overflow pass rasterizes it
        const uint first = t.firstEntry;
        const Edges e = edgesOf(t, bits, size);
        const ivec4 tiles = ivec4(e.bbox.xy / RASTER_TILE_SIZE, e.bbox.zw / RASTER_TILE_SIZE);
        const int w = tiles.z - tiles.x + 1;
        const uint n = uint(w * (tiles.w - tiles.y + 1));
        for (uint i = gl_LocalInvocationIndex; i < n; i += RASTER_BIN_GROUP) {
            const ivec2 tile = tiles.xy + ivec2(int(i) % w, int(i) / w);
            const bool may = tileMayCover(e, tileRect(tile, e.bbox), bits);
            tileEntries[first + i] = uvec2(may ? r : RASTER_NO_RECORD, uint(tile.x) | (uint(tile.y) << 16));
            if (may) atomicAdd(tileBins[tileIndex(t.layer, tile, size)].x, 1u);
        }
    }
}
