#version 460
// Triangle setup of the compute rasterizer (src/raster): one thread per (triangle, layer), every
// layer of every light in one dispatch (y = row of the layer table); raster/setup.glsl sets each up.
// A small triangle (bounding box within RASTER_SMALL_EXTENT pixels) is rasterized right here, as
// Nanite's compute rasterizer does; a large one is stored with an entry reserved per tile of its box,
// which the bin pass fills (Laine & Karras 2011's coarse stage, one list of (triangle, tile) entries).
// A large triangle that does not fit the lists is never rasterized here (one thread through a
// layer-sized triangle is the cost that grows with the layer): its (triangle, layer) pair is queued
// for the overflow pass, which spreads it over workgroups of a bounded number of tiles each.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "raster/setup.glsl"

layout(local_size_x = RASTER_SETUP_GROUP) in;

uint mostPixels = 0u;          // the most pixels this thread tested for one triangle (work.x)
bool pairOverflowed = false;  // a large triangle of this pair did not fit the lists
uint pairMostTiles = 0u;      // the largest box (tiles) of the pair's large triangles, binned or not
bool inlineLarge = false;     // the overflow queue is full too: rasterize large ones here (counts.z)

// Stores a large triangle and reserves one tile entry per tile of its box (the bin pass fills them
// in parallel: binning a layer-sized triangle here took one thread through 4096 tiles); false when
// a list is full (the caller queues its pair for the overflow pass).
bool bin(RasterTriangle t, Edges e) {
    const uint record = atomicAdd(counters.records, 1u);
    if (record >= push.recordCapacity) return false;
    const ivec4 tiles = ivec4(e.bbox.xy / RASTER_TILE_SIZE, e.bbox.zw / RASTER_TILE_SIZE);
    const uint n = uint((tiles.z - tiles.x + 1) * (tiles.w - tiles.y + 1));
    // Once the entries are taken, no more are counted: the count cannot wrap around 2^32 and seem to
    // fit again (only the threads between this read and their add overshoot).
    const uint first = counters.tileEntries > push.entryCapacity ? push.entryCapacity + 1u : atomicAdd(counters.tileEntries, n);
    const bool fits = first <= push.entryCapacity && n <= push.entryCapacity - first;
    t.firstEntry = fits ? first : RASTER_NO_ENTRY;
    records[record] = t;
    return fits;
}

// Marks the tiles of a box that this thread draws into (RASTER_TILE_TOUCHED): the tile pass reads
// the depth of marked tiles only, and starts the others from the cleared value.
void markTiles(uint layer, ivec4 box, ivec2 size) {
    const ivec4 tiles = box / RASTER_TILE_SIZE;
    for (int y = tiles.y; y <= tiles.w; ++y)
        for (int x = tiles.x; x <= tiles.z; ++x) {
            const uint bin = tileIndex(layer, ivec2(x, y), size);
            if ((tileBins[bin].w & RASTER_TILE_TOUCHED) == 0u) atomicOr(tileBins[bin].w, RASTER_TILE_TOUCHED);
        }
}

void takeTriangle(RasterTriangle t, Edges e, int bits, ivec2 size) {
    const bool small = isSmall(e);
    if (!small && !inlineLarge) {
        pairMostTiles = max(pairMostTiles, boxTiles(e));
        if (!bin(t, e)) pairOverflowed = true;
        return;
    }
    if (!small) atomicAdd(counters.inlined, 1u);
    markTiles(t.layer, e.bbox, size);
    mostPixels = max(mostPixels, uint(e.bbox.z - e.bbox.x + 1) * uint(e.bbox.w - e.bbox.y + 1));
    if (small && bits <= 8 && smallEnough(e))
        rasterizeSmall(t, e, bits, size);
    else
        rasterizeRect(t, e, e.bbox, bits, size);
}

// Queues a pair whose large triangles did not fit for the overflow pass: in the medium queue when
// every large triangle's box is at most RASTER_OVERFLOW_TILES tiles (one workgroup each), else in the
// huge queue (split into parts). When its queue is full too (a last resort that the capacity, a slot
// per pair, keeps away), sets the pair up again rasterizing its large triangles here.
void queueOverflow(uint drawn, uint row, RasterLayer target) {
    atomicAdd(work.y, 1u);
    const bool huge = pairMostTiles > RASTER_OVERFLOW_TILES;
    const uint slot = huge ? atomicAdd(queues.y, 1u) : atomicAdd(queues.x, 1u);
    if (slot < overflowQueueCapacity()) {
        overflowPairs[(huge ? overflowQueueCapacity() : 0u) + slot] = uvec2(drawn, row);
        if (huge) atomicMax(work.w, pairMostTiles);
        return;
    }
    inlineLarge = true;
    setupTriangle(drawn, target);
    inlineLarge = false;
}

void main() {
    const uint stride = gl_NumWorkGroups.x * RASTER_SETUP_GROUP;
    const uint row = gl_GlobalInvocationID.y;
    const RasterLayer target = rasterLayers[row];
    for (uint t = gl_GlobalInvocationID.x; t < push.triangleCount; t += stride) {
        pairOverflowed = false;
        pairMostTiles = 0u;
        setupTriangle(t, target);
        if (pairOverflowed) queueOverflow(t, row, target);
    }
    const uint most = subgroupMax(mostPixels);
    if (subgroupElect() && most > 0u) atomicMax(work.x, most);
}
