// The compute rasterizer (src/raster): the structs and constants its passes share between C++ and GLSL,
// laid out by the rules of shared/types.h, which includes this file (its includers see them all).
#ifndef PENUMBRA_RASTER_TYPES_H
#define PENUMBRA_RASTER_TYPES_H

#include "shared/types.h"

#ifdef __cplusplus
namespace penumbra::gpu {
#endif

// Triangles whose pixel bounding box fits RASTER_SMALL_EXTENT on both sides are rasterized by the
// thread that set them up; larger ones are binned into RASTER_TILE_SIZE tiles, one workgroup per tile.
#define RASTER_SMALL_EXTENT 16
#define RASTER_TILE_SIZE 32
#define RASTER_SETUP_GROUP 64
#define RASTER_TILE_GROUP 256
#define RASTER_BIN_GROUP 64
#define RASTER_PLACE_GROUP 256
#define RASTER_TILE_TOUCHED 0x80000000u  // tile bin flag: a setup thread drew into the tile
// The depth buffers' clear values: 1.0 (far) in a depth layer; in each 32-bit half of an ID layer's
// depth << 32 | ID just above 1.0, so that a triangle at exactly the far plane still writes its ID
// (the hardware's test is LESS_OR_EQUAL) and the split reads an untouched texel as far and no ID.
#define RASTER_FAR_BITS 0x3F800000u
#define RASTER_ID_CLEAR_BITS 0x3F800001u
#define RASTER_SCATTER_GROUP 256
#define RASTER_NO_RECORD 0xFFFFFFFFu   // a tile entry whose triangle went the inline path (lists full)

// One triangle after setup (clipped, snapped, front-facing or double-sided, non-empty), in window
// coordinates of its layer: what coverage, depth and the alpha test need.
struct RasterTriangle {
    uvec4 xy01;      // snapped vertices 0 and 1 (int bits, subpixel units): x0, y0, x1, y1
    uvec4 xy2;       // x2, y2 (int bits), z = target layer, w = material
    vec4 origin;     // xy = float window position of vertex 0 (origin of the uv planes), z = 1: alpha-tested,
                     // w = its first tile entry (-1: the lists were full)
    vec4 depth;      // plane of z: value at pixel (0, 0) (integer pixel coordinates, as lavapipe), d/dx, d/dy;
                     // w = depth bias of the triangle
    vec4 uOverW;     // planes of u/w, v/w and 1/w (perspective-correct uv): value at origin, d/dx, d/dy
    vec4 vOverW;
    vec4 invW;
    uvec4 ids;       // x = visibility ID (drawn triangle + 1), y = ID layer + 1 (0: a depth-only layer), zw unused
};

// One layer the compute rasterizer draws (a host-written table: every layer of every light it
// draws is one row of the setup dispatch).
struct RasterLayer {
    uint viewRow;
    uint targetLayer;
    uint skipBlended;     // 1: alphaMode BLEND casters are skipped (a deep shadow map takes them)
    uint idLayerPlusOne;  // ID layer + 1 (0: depth only; else depth and visibility IDs)
};

// Push constants of the compute rasterizer's passes.
struct RasterPush {
    uint width;
    uint subpixelBits;    // subpixel precision bits
    uint triangleCount;
    uint layerCount;
    uint recordCapacity;  // triangle records
    uint entryCapacity;   // tile entries
    uint smallExtent;     // small-triangle extent (pixels)
    uint height;
    float biasConstant;   // depth bias: constant factor
    float biasSlope;      // slope factor
    uint frontsCounterClockwise;  // 1: a y-flipped projection (the camera)
    uint pad0;
};

// Counters of one frame's binning (cleared before setup).
struct RasterCounters {
    uint records;      // triangle records taken
    uint tileEntries;  // tile entries taken
    uint inlined;      // triangles rasterized inline because a list was full
    uint placed;       // tile-list entries placed (raster/place.comp)
};

#ifdef __cplusplus
static_assert(sizeof(RasterTriangle) == 128 && sizeof(RasterLayer) == 16 && sizeof(RasterPush) == 48 &&
              offsetof(RasterPush, biasConstant) == 32 && sizeof(RasterCounters) == 16);
}  // namespace penumbra::gpu
#endif
#endif
