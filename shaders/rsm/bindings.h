// Binding numbers of the RSM passes' set 0, included by their GLSL (layout(binding = ...)) and by
// the C++ that declares the layouts and binds the resources (src/rsm): each number is written here
// only. tests/spirv_reflection_test.cpp checks the compiled modules against the C++ declarations.
#ifndef PENUMBRA_RSM_BINDINGS_H
#define PENUMBRA_RSM_BINDINGS_H

// rsm/gather.glsl: every gather pipeline.
#define RSM_GATHER_FRAME 0
#define RSM_GATHER_GBUFFER_NORMAL 1
#define RSM_GATHER_GBUFFER_DEPTH 2
#define RSM_GATHER_RSM_DEPTH 3
#define RSM_GATHER_RSM_NORMAL 4
#define RSM_GATHER_RSM_FLUX 5
#define RSM_GATHER_LAYERS 6
#define RSM_GATHER_SAMPLES 7
#define RSM_GATHER_IRRADIANCE 8
#define RSM_GATHER_PIXEL_LIST 9
#define RSM_GATHER_OCCUPANCY 10
#define RSM_GATHER_VPLS 11
#define RSM_GATHER_FLUX_DRAWS 12
#define RSM_GATHER_GRADIENT_SAMPLES 13  // written by RSM_GATHER_LOWRES, read by RSM_GATHER_GRADIENT

// rsm/interpolate.comp.
#define RSM_INTERPOLATE_FRAME 0
#define RSM_INTERPOLATE_GBUFFER_NORMAL 1
#define RSM_INTERPOLATE_GBUFFER_DEPTH 2
#define RSM_INTERPOLATE_LOW_IRRADIANCE 3
#define RSM_INTERPOLATE_IRRADIANCE 4
#define RSM_INTERPOLATE_PIXEL_LIST 5
#define RSM_INTERPOLATE_LAYERS 6

// rsm/resolve.comp; bindings 0-2 are the scene's resolve set (SceneGpu::resolveSetBindings).
#define RSM_RESOLVE_LIGHTS 3
#define RSM_RESOLVE_LAYERS 4
#define RSM_RESOLVE_SHADOW_IDS 5
#define RSM_RESOLVE_DEPTH 6
#define RSM_RESOLVE_NORMAL 7
#define RSM_RESOLVE_FLUX 8
#define RSM_RESOLVE_VPLS 9

// rsm/flux_sums.comp and rsm/flux_draw.comp.
#define RSM_FLUX_VPLS 0
#define RSM_FLUX_SUMS 1
#define RSM_FLUX_DRAWS 2

#endif
