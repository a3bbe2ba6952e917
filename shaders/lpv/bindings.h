// Binding numbers of the LPV passes' set 0, included by their GLSL (layout(binding = ...)) and by
// the C++ that declares the layouts and binds the resources (src/lpv): each number is written here
// only. tests/spirv_reflection_test.cpp checks the compiled modules against the C++ declarations.
#ifndef PENUMBRA_LPV_BINDINGS_H
#define PENUMBRA_LPV_BINDINGS_H

// lpv/downsample.comp: the RSM's texels to VPLs.
#define LPV_DOWNSAMPLE_RSM_DEPTH 0
#define LPV_DOWNSAMPLE_RSM_NORMAL 1
#define LPV_DOWNSAMPLE_RSM_FLUX 2
#define LPV_DOWNSAMPLE_LAYERS 3
#define LPV_DOWNSAMPLE_LIGHTS 4
#define LPV_DOWNSAMPLE_VPLS 5

// lpv/inject_range.comp.
#define LPV_RANGE_VPLS 0
#define LPV_RANGE_RANGES 1

// lpv/inject.comp.
#define LPV_INJECT_VPLS 0
#define LPV_INJECT_LIGHT_SUMS 1
#define LPV_INJECT_GEOMETRY_SUMS 2
#define LPV_INJECT_RANGES 3

// lpv/inject_camera.comp.
#define LPV_CAMERA_FRAME 0
#define LPV_CAMERA_GBUFFER_NORMAL 1
#define LPV_CAMERA_GBUFFER_DEPTH 2
#define LPV_CAMERA_GEOMETRY_SUMS 3

// inject_sky.comp
#define LPV_SKY_FRAME 0
#define LPV_SKY_GBUFFER_ALBEDO 1
#define LPV_SKY_GBUFFER_NORMAL 2
#define LPV_SKY_GBUFFER_DEPTH 3
#define LPV_SKY_IRRADIANCE 4
#define LPV_SKY_VPLS 5

// lpv/resolve.comp.
#define LPV_RESOLVE_LIGHT_SUMS 0
#define LPV_RESOLVE_GEOMETRY_SUMS 1
#define LPV_RESOLVE_RANGES 2
#define LPV_RESOLVE_LIGHT 3
#define LPV_RESOLVE_GEOMETRY 4

// lpv/face_transmittance.comp.
#define LPV_FACES_OCCUPANCY 0
#define LPV_FACES_OUT 1

// lpv/propagate.comp.
#define LPV_PROPAGATE_SOURCE 0
#define LPV_PROPAGATE_DESTINATION 1
#define LPV_PROPAGATE_SUM 2
#define LPV_PROPAGATE_GEOMETRY 3
#define LPV_PROPAGATE_FACES 4

// lpv/gather.comp.
#define LPV_GATHER_FRAME 0
#define LPV_GATHER_GBUFFER_NORMAL 1
#define LPV_GATHER_GBUFFER_DEPTH 2
#define LPV_GATHER_SUM 3
#define LPV_GATHER_GEOMETRY 4
#define LPV_GATHER_IRRADIANCE 5

// lpv/gradient.comp.
#define LPV_GRADIENT_FRAME 0
#define LPV_GRADIENT_GBUFFER_NORMAL 1
#define LPV_GRADIENT_GBUFFER_DEPTH 2
#define LPV_GRADIENT_SUM 3
#define LPV_GRADIENT_KEPT_SUM 4
#define LPV_GRADIENT_KEPT_CASCADES 5
#define LPV_GRADIENT_CHANGE 6

#endif
