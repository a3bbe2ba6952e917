#version 460
// Tile lists of the compute rasterizer (src/raster): each (triangle, tile) entry of the bin pass puts
// its record into its tile's list, at the tile's offset (place pass) plus a slot from the tile's cursor.
// One thread per entry; the workgroups stride over the rest. Entries of triangles whose lists did
// not fit were never written (the overflow pass rasterized them): a stale one still names a record
// of this frame in a tile of its layer (the tile pass tests its edges), and none writes past its
// tile's count.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "raster/raster.glsl"

layout(local_size_x = RASTER_SCATTER_GROUP) in;
layout(push_constant) uniform Push { RasterPush push; };

void main() {
    const ivec2 size = ivec2(push.width, push.height);
    const uint entries = min(counters.tileEntries, push.entryCapacity);
    const uint recordCount = min(counters.records, push.recordCapacity);
    for (uint k = gl_GlobalInvocationID.x; k < entries; k += gl_NumWorkGroups.x * RASTER_SCATTER_GROUP) {
        const uvec2 entry = tileEntries[k];
        if (entry.x >= recordCount) continue;  // RASTER_NO_RECORD, or stale
        const uint bin = tileIndex(records[entry.x].layer, ivec2(entry.y & 0xFFFFu, entry.y >> 16), size);
        const uint slot = atomicAdd(tileBins[bin].z, 1u);
        if (slot < tileBins[bin].x) tileLists[tileBins[bin].y + slot] = entry.x;
    }
}
