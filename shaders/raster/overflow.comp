#version 460
// The overflow pass of the compute rasterizer (src/raster): the large triangles of the (triangle,
// layer) pairs that the setup pass could not bin (the tile lists were full). Workgroup (x, y) sets up
// queued pair x again (raster/setup.glsl) and rasterizes part y of each of its large triangles: the
// tiles of the triangle's box whose index is y modulo the parts (gl_NumWorkGroups.y). Two dispatches:
// the medium queue with one part (every box at most RASTER_OVERFLOW_TILES tiles), the huge queue with
// enough parts for its largest box (raster/args.comp; at least 2, which tells the queues apart), so
// that no workgroup takes more than RASTER_OVERFLOW_TILES tiles of a triangle at any layer size. Its
// threads share each tile's pixels; depth by atomicMin as the setup pass's small triangles, before
// the tile pass, which reads the tiles marked touched here.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "raster/setup.glsl"

layout(local_size_x = RASTER_OVERFLOW_GROUP) in;

uint mostPixels = 0u;  // the most pixels this thread tested for one triangle (work.z)

void takeTriangle(RasterTriangle t, Edges e, int bits, ivec2 size) {
    if (isSmall(e)) return;  // the setup pass rasterized it
    const ivec4 tiles = e.bbox / RASTER_TILE_SIZE;
    const int across = tiles.z - tiles.x + 1;
    const uint n = boxTiles(e);
    uint tested = 0u;
    for (uint i = gl_WorkGroupID.y; i < n; i += gl_NumWorkGroups.y) {
        const ivec2 tile = tiles.xy + ivec2(int(i) % across, int(i) / across);
        const ivec4 rect = tileRect(tile, e.bbox);
        if (!tileMayCover(e, rect, bits)) continue;
        if (gl_LocalInvocationIndex == 0u) atomicOr(tileBins[tileIndex(t.layer, tile, size)].w, RASTER_TILE_TOUCHED);
        const int width = rect.z - rect.x + 1, pixels = width * (rect.w - rect.y + 1);
        for (int k = int(gl_LocalInvocationIndex); k < pixels; k += RASTER_OVERFLOW_GROUP, ++tested) {
            const ivec2 p = rect.xy + ivec2(k % width, k / width);
            if (covers(e, p, bits)) shadeSample(t, p, size);
        }
    }
    mostPixels = max(mostPixels, tested);
}

void main() {
    const bool huge = gl_NumWorkGroups.y > 1u;
    const uint first = huge ? overflowQueueCapacity() : 0u;
    const uint queued = min(huge ? queues.y : queues.x, overflowQueueCapacity());
    for (uint q = gl_WorkGroupID.x; q < queued; q += gl_NumWorkGroups.x) {
        const uvec2 pair = overflowPairs[first + q];
        setupTriangle(pair.x, rasterLayers[pair.y]);
    }
    const uint most = subgroupMax(mostPixels);
    if (subgroupElect() && most > 0u) atomicMax(work.z, most);
}
