// Binding numbers of the compute rasterizer's passes (set 0), included by their GLSL and by
// src/raster/compute_raster.cpp: each number is written here only. The main set starts with the
// scene's draw set (views, materials, instances: core/scene_bindings.h; set 1 its textures).
// tests/spirv_reflection_test.cpp checks the compiled modules against the C++ declarations.
#ifndef PENUMBRA_RASTER_BINDINGS_H
#define PENUMBRA_RASTER_BINDINGS_H

// raster/raster.glsl and its passes (setup, overflow, bin, scatter, tiles).
#define RASTER_SET_DEPTH 3         // depth bits per texel of every layer
#define RASTER_SET_RECORDS 4       // RasterTriangle per large triangle
#define RASTER_SET_TILE_ENTRIES 5
#define RASTER_SET_COUNTERS 6      // RasterCounters, then the work counters and queues
#define RASTER_SET_VERTICES 7      // the scene's (setup, overflow)
#define RASTER_SET_INDICES 8
#define RASTER_SET_TRIANGLE_MATERIALS 9
#define RASTER_SET_LAYERS 10       // RasterLayer per drawn layer
#define RASTER_SET_DRAWN_TRIANGLES 11
#define RASTER_SET_TILE_BINS 12
#define RASTER_SET_TILE_LISTS 13
#define RASTER_SET_DEPTH_IDS 16    // depth << 32 | ID per texel of the ID layers
#define RASTER_SET_TARGET 17       // tiles_image*.comp: the R32_SFLOAT target
#define RASTER_SET_ID_IMAGE 18     // and its visibility IDs
#define RASTER_SET_OVERFLOW_PAIRS 19

// raster/ids.glsl: the split of depth << 32 | ID.
#define RASTER_IDS_DEPTH 0
#define RASTER_IDS_DEPTH_IDS 1
#define RASTER_IDS_LAYERS 2
#define RASTER_IDS_IMAGE 3

// raster/place.comp.
#define RASTER_PLACE_TILE_BINS 0
#define RASTER_PLACE_COUNTERS 1

// raster/args.comp.
#define RASTER_ARGS_COUNTERS 0
#define RASTER_ARGS_DISPATCH 1
#define RASTER_ARGS_OVERFLOW_PAIRS 2

#endif
