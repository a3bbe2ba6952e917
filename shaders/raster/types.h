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
// coordinates of its layer: what coverage, depth and the alpha test need. Eight 16-byte groups, each
// read whole where the passes read it together (raster/tiles.glsl loads a batch one group a thread);
// a plane is (value at its reference point, d/dx, d/dy).
struct RasterTriangle {
    ivec2 vertex0;        // snapped vertices (subpixel units)
    ivec2 vertex1;
    ivec2 vertex2;
    uint layer;           // the target layer
    uint material;
    vec2 origin;          // float window position of vertex 0: the reference point of the uv planes
    uint alphaTested;     // 1: the material's alpha test applies
    uint firstEntry;      // the triangle's first tile entry (RASTER_NO_ENTRY: the lists were full)
    vec3 depthPlane;      // z at integer pixel coordinates, as lavapipe interpolates it
    float depthBias;      // the triangle's depth bias, added to the plane's value
    vec3 uOverW;          // planes of u/w, v/w and 1/w (perspective-correct uv), at origin
    uint pad0;
    vec3 vOverW;
    uint pad1;
    vec3 invW;
    uint pad2;
    uint visibilityId;    // drawn triangle + 1
    uint idLayerPlusOne;  // ID layer + 1 (0: a depth-only layer)
    uint pad3;
    uint pad4;
};
#define RASTER_NO_ENTRY 0xFFFFFFFFu  // RasterTriangle.firstEntry of a triangle that got no tile entries

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
static_assert(sizeof(RasterTriangle) == 128 && offsetof(RasterTriangle, vertex0) == 0 &&
              offsetof(RasterTriangle, vertex1) == 8 && offsetof(RasterTriangle, vertex2) == 16 &&
              offsetof(RasterTriangle, layer) == 24 && offsetof(RasterTriangle, material) == 28 &&
              offsetof(RasterTriangle, origin) == 32 && offsetof(RasterTriangle, alphaTested) == 40 &&
              offsetof(RasterTriangle, firstEntry) == 44 && offsetof(RasterTriangle, depthPlane) == 48 &&
              offsetof(RasterTriangle, depthBias) == 60 && offsetof(RasterTriangle, uOverW) == 64 &&
              offsetof(RasterTriangle, pad0) == 76 && offsetof(RasterTriangle, vOverW) == 80 &&
              offsetof(RasterTriangle, pad1) == 92 && offsetof(RasterTriangle, invW) == 96 &&
              offsetof(RasterTriangle, pad2) == 108 && offsetof(RasterTriangle, visibilityId) == 112 &&
              offsetof(RasterTriangle, idLayerPlusOne) == 116 && offsetof(RasterTriangle, pad3) == 120 &&
              offsetof(RasterTriangle, pad4) == 124);
static_assert(sizeof(RasterLayer) == 16 && sizeof(RasterPush) == 48 && offsetof(RasterPush, biasConstant) == 32 &&
              sizeof(RasterCounters) == 16);
}  // namespace penumbra::gpu
#endif
#endif
