// The body of raster/tiles*.comp. Fine rasterization of large triangles (src/raster): one workgroup
// per tile of each layer drawn (z = row of the layer table), over the tile's list of triangles (bin,
// place and scatter passes). Each thread owns RASTER_TILE_SIZE^2 / RASTER_TILE_GROUP pixels of the
// tile (a column, every kRowsPerPass-th row): it reads their depth once where a setup thread drew
// into the tile (small triangles), keeps the nearest depth << 32 | ID of each in registers while it
// walks the list, and writes them once. No atomics, no depth traffic per triangle (the tiled depth
// test of Laine & Karras 2011); the result equals the atomicMin of every covered sample (ties: the
// smaller ID). RASTER_TARGET_IMAGE: every pixel of every tile goes straight into the R32_SFLOAT
// target (and the ID image), so no split or store pass follows (RASTER_ID_IMAGE_2D: the camera's
// 2D images); else changed pixels go back into the depth buffers (a copy then fills a D32 target).
layout(local_size_x = RASTER_TILE_GROUP) in;
#include "raster/bindings.h"
layout(set = 0, binding = RASTER_SET_LAYERS, std430) readonly buffer Layers { RasterLayer rasterLayers[]; };
#ifdef RASTER_TARGET_IMAGE
#ifdef RASTER_ID_IMAGE_2D
layout(set = 0, binding = RASTER_SET_TARGET, r32f) uniform writeonly image2D depthMap;
layout(set = 0, binding = RASTER_SET_ID_IMAGE, r32ui) uniform writeonly uimage2D idMap;
#define TARGET_TEXEL(p, layer) ivec2(p)
#else
layout(set = 0, binding = RASTER_SET_TARGET, r32f) uniform writeonly image2DArray depthMap;
layout(set = 0, binding = RASTER_SET_ID_IMAGE, r32ui) uniform writeonly uimage2DArray idMap;
#define TARGET_TEXEL(p, layer) ivec3(p, layer)
#endif
#endif

layout(push_constant) uniform Push { RasterPush push; };

const int kRowsPerPass = RASTER_TILE_GROUP / RASTER_TILE_SIZE;
const int kPixels = RASTER_TILE_SIZE / kRowsPerPass;  // per thread
// The list is walked in batches: the workgroup loads a batch's records into shared memory together
// (one 16-byte group per thread), so a triangle costs no dependent global load in the walk.
const uint kGroupsPerRecord = 8u;  // sizeof(RasterTriangle) / 16
const uint kBatch = RASTER_TILE_GROUP / kGroupsPerRecord;
shared RasterTriangle batch[kBatch];

void loadBatch(uint first, uint n) {
    const uint r = gl_LocalInvocationIndex / kGroupsPerRecord;
    if (r >= n) return;
    const uint record = tileLists[first + r];
    // Every field of the group, padding too: each thread moves four adjacent words.
    switch (gl_LocalInvocationIndex % kGroupsPerRecord) {  // one 16-byte group of the record per thread
        case 0u:
            batch[r].vertex0 = records[record].vertex0;
            batch[r].vertex1 = records[record].vertex1;
            break;
        case 1u:
            batch[r].vertex2 = records[record].vertex2;
            batch[r].layer = records[record].layer;
            batch[r].material = records[record].material;
            break;
        case 2u:
            batch[r].origin = records[record].origin;
            batch[r].alphaTested = records[record].alphaTested;
            batch[r].firstEntry = records[record].firstEntry;
            break;
        case 3u:
            batch[r].depthPlane = records[record].depthPlane;
            batch[r].depthBias = records[record].depthBias;
            break;
        case 4u:
            batch[r].uOverW = records[record].uOverW;
            batch[r].pad0 = records[record].pad0;
            break;
        case 5u:
            batch[r].vOverW = records[record].vOverW;
            batch[r].pad1 = records[record].pad1;
            break;
        case 6u:
            batch[r].invW = records[record].invW;
            batch[r].pad2 = records[record].pad2;
            break;
        default:
            batch[r].visibilityId = records[record].visibilityId;
            batch[r].idLayerPlusOne = records[record].idLayerPlusOne;
            batch[r].pad3 = records[record].pad3;
            batch[r].pad4 = records[record].pad4;
            break;
    }
}

// Writes a thread's pixels: into the target images (every pixel in the target), or the changed
// ones back into the depth buffers.
void storePixels(uint64_t nearest[kPixels], uint64_t first[kPixels], uint index[kPixels], ivec2 origin, ivec2 size,
                 uint layer, uint idLayer) {
    const uint kFar = RASTER_FAR_BITS;  // an ID layer is cleared just above it (RASTER_ID_CLEAR_BITS)
    for (int k = 0; k < kPixels; ++k) {
        const ivec2 p = origin + ivec2(0, k * kRowsPerPass);
        if (p.y >= size.y || p.x >= size.x) continue;
#ifdef RASTER_TARGET_IMAGE
        const uint bits = uint(nearest[k] >> 32);
        imageStore(depthMap, TARGET_TEXEL(p, layer), vec4(uintBitsToFloat(min(bits, kFar))));
        if (idLayer != 0u) imageStore(idMap, TARGET_TEXEL(p, idLayer - 1u), uvec4(bits > kFar ? 0u : uint(nearest[k])));
#else
        if (nearest[k] == first[k]) continue;
        if (idLayer != 0u)
            depthIds[index[k]] = nearest[k];
        else
            depthBits[index[k]] = uint(nearest[k] >> 32);
#endif
    }
}

void main() {
    const ivec2 size = ivec2(push.width, push.height);
    const int bits = int(push.subpixelBits);
    const RasterLayer row = rasterLayers[gl_WorkGroupID.z];
    const uint layer = row.targetLayer, idLayer = row.idLayerPlusOne;  // ID layer + 1, or 0: depth only
    const ivec2 tile = ivec2(gl_WorkGroupID.xy);
    const uvec4 bin = tileBins[tileIndex(layer, tile, size)];
    const uint count = min(bin.x, bin.z);
    const bool touched = (bin.w & RASTER_TILE_TOUCHED) != 0u;
#ifndef RASTER_TARGET_IMAGE
    if (count == 0u) return;  // the buffers hold what the setup threads drew
#endif
    const ivec2 lane = ivec2(int(gl_LocalInvocationIndex) % RASTER_TILE_SIZE,
                             int(gl_LocalInvocationIndex) / RASTER_TILE_SIZE);
    const ivec2 origin = tile * RASTER_TILE_SIZE + lane;
    // The clear values (ComputeRaster::addTo).
    const uint64_t cleared = idLayer != 0u ? uint64_t(RASTER_ID_CLEAR_BITS) << 32 | RASTER_ID_CLEAR_BITS
                                           : uint64_t(RASTER_FAR_BITS) << 32;
    uint64_t nearest[kPixels];
    uint index[kPixels];
    for (int k = 0; k < kPixels; ++k) {
        const ivec2 p = min(origin + ivec2(0, k * kRowsPerPass), size - 1);
        index[k] = ((idLayer != 0u ? idLayer - 1u : layer) * uint(size.y) + uint(p.y)) * uint(size.x) + uint(p.x);
        nearest[k] = !touched ? cleared : idLayer != 0u ? depthIds[index[k]] : uint64_t(depthBits[index[k]]) << 32;
    }
    const uint64_t first[kPixels] = nearest;
    for (uint start = 0u; start < count; start += kBatch) {
        const uint n = min(count - start, kBatch);
        barrier();  // the previous batch is walked
        loadBatch(bin.y + start, n);
        barrier();
        for (uint i = 0u; i < n; ++i) {
            const RasterTriangle t = batch[i];
            const Edges e = edgesOf(t, bits, size);
            // The edge functions at the thread's first pixel, then one 64-bit add per pixel below it.
            i64vec3 edge, step;
            for (int j = 0; j < 3; ++j) {
                const i64vec2 q = i64vec2((origin << bits) + (1 << (bits - 1))) - e.a[j];
                edge[j] = e.d[j].x * q.y - e.d[j].y * q.x + e.bias[j];
                step[j] = e.d[j].x * int64_t(kRowsPerPass << bits);
            }
            // A covered centre lies in the triangle's box, so the edges alone decide (pixels beyond
            // the target, in its last row or column of tiles, are never stored).
            for (int k = 0; k < kPixels; ++k, edge += step) {
                const ivec2 p = origin + ivec2(0, k * kRowsPerPass);
                if (any(lessThan(edge, i64vec3(0l)))) continue;
                const uint64_t v =
                    uint64_t(sampleDepthBits(t, p)) << 32 | uint64_t(idLayer != 0u ? t.visibilityId : 0u);
                if (v < nearest[k] && !(t.alphaTested != 0u && alphaDiscarded(t, vec2(p) + 0.5 - t.origin)))
                    nearest[k] = v;
            }
        }
    }
    storePixels(nearest, first, index, origin, size, layer, idLayer);
}
