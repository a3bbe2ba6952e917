// Binding numbers of the shadow passes' set 0, included by their GLSL and by the C++ that declares
// the layouts and binds the resources (src/shadow): each number is written here only. The shadow
// raster passes draw with the scene's draw set (core/scene_bindings.h). tests/spirv_reflection_test.cpp
// checks the compiled modules against the C++ declarations.
#ifndef PENUMBRA_SHADOW_BINDINGS_H
#define PENUMBRA_SHADOW_BINDINGS_H

// shadow/filter.comp: the shadow mask.
#define SHADOW_MASK_FRAME 0
#define SHADOW_MASK_LIGHTS 1
#define SHADOW_MASK_GBUFFER_DEPTH 2
#define SHADOW_MASK_GBUFFER_NORMAL 3
#define SHADOW_MASK_DEPTH_MAP 4
#define SHADOW_MASK_MOMENTS 5
#define SHADOW_MASK_LAYERS 6
#define SHADOW_MASK_SHADOW_LIGHTS 7
#define SHADOW_MASK_PARAMS 8
#define SHADOW_MASK_OUT 9

// shadow/moments_x.comp: the moments along rows.
#define MOMENT_ROWS_DEPTH_MAP 0
#define MOMENT_ROWS_OUT 1
#define MOMENT_ROWS_LAYERS 2
#define MOMENT_ROWS_PARAMS 3

// shadow/moments_y.comp: then along columns.
#define MOMENT_COLUMNS_ROWS 0
#define MOMENT_COLUMNS_OUT 1
#define MOMENT_COLUMNS_LAYERS 2
#define MOMENT_COLUMNS_PARAMS 3

#endif
