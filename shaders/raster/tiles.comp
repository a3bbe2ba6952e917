#version 460
// Fine rasterization of large triangles (src/raster): one workgroup per tile of a target layer, over
// the tile's list of triangles (bin, scan and scatter passes). Each thread owns RASTER_TILE_SIZE^2 /
// RASTER_TILE_GROUP pixels of the tile (a column, every kRowsPerPass-th row): it reads their depth
// once (the setup pass's small triangles are in it), keeps the nearest depth << 32 | ID of each in
// registers while it walks the list, and writes the changed ones once. No atomics, no depth traffic
// per triangle (the tiled depth test of Laine & Karras 2011); the result equals the atomicMin of
// every covered sample (ties: the smaller ID). Tiles with an empty list return at once.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "raster/raster.glsl"

layout(local_size_x = RASTER_TILE_GROUP) in;

layout(push_constant) uniform Push { RasterPush push; };

const int kRowsPerPass = RASTER_TILE_GROUP / RASTER_TILE_SIZE;
const int kPixels = RASTER_TILE_SIZE / kRowsPerPass;  // per thread

void main() {
    const ivec2 size = ivec2(push.target.x, push.capacity.w);
    const int bits = int(push.target.y);
    const uint layer = gl_WorkGroupID.z;
    const ivec2 tile = ivec2(gl_WorkGroupID.xy);
    const uvec4 bin = tileBins[tileIndex(layer, tile, size)];
    const uint count = min(bin.x, bin.z);
    if (count == 0u) return;
    const ivec2 lane = ivec2(int(gl_LocalInvocationIndex) % RASTER_TILE_SIZE,
                             int(gl_LocalInvocationIndex) / RASTER_TILE_SIZE);
    const ivec2 origin = tile * RASTER_TILE_SIZE + lane;
    // A layer either has IDs (every triangle of it carries the same ID layer) or is depth only.
    const uint idLayer = records[tileLists[bin.y]].ids.y;
    uint64_t nearest[kPixels];
    uint index[kPixels];
    for (int k = 0; k < kPixels; ++k) {
        const ivec2 p = min(origin + ivec2(0, k * kRowsPerPass), size - 1);
        index[k] = ((idLayer != 0u ? idLayer - 1u : layer) * uint(size.y) + uint(p.y)) * uint(size.x) + uint(p.x);
        nearest[k] = idLayer != 0u ? depthIds[index[k]] : uint64_t(depthBits[index[k]]) << 32;
    }
    const uint64_t first[kPixels] = nearest;
    for (uint i = 0u; i < count; ++i) {
        const RasterTriangle t = records[tileLists[bin.y + i]];
        const Edges e = edgesOf(t, bits, size);
        for (int k = 0; k < kPixels; ++k) {
            const ivec2 p = origin + ivec2(0, k * kRowsPerPass);
            if (any(lessThan(p, e.bbox.xy)) || any(greaterThan(p, e.bbox.zw)) || !covers(e, p, bits)) continue;
            const uint64_t v = uint64_t(sampleDepthBits(t, p)) << 32 | uint64_t(idLayer != 0u ? t.ids.x : 0u);
            if (v < nearest[k] && !(t.origin.z != 0.0 && alphaDiscarded(t, vec2(p) + 0.5 - t.origin.xy)))
                nearest[k] = v;
        }
    }
    for (int k = 0; k < kPixels; ++k) {
        if (nearest[k] == first[k] || origin.y + k * kRowsPerPass >= size.y || origin.x >= size.x) continue;
        if (idLayer != 0u)
            depthIds[index[k]] = nearest[k];
        else
            depthBits[index[k]] = uint(nearest[k] >> 32);
    }
}
