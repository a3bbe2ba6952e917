// Binding numbers of the DSM, DOM, hair and camera translucency passes (set 0), included by their
// GLSL and by the C++ that declares the layouts and binds the resources (src/dsm): each number is
// written here only. The raster builds draw with the scene's draw set (core/scene_bindings.h) beside
// these. tests/spirv_reflection_test.cpp checks the compiled modules against the C++ declarations.
#ifndef PENUMBRA_DSM_BINDINGS_H
#define PENUMBRA_DSM_BINDINGS_H

// Every ribbon pass (dsm/ribbon.glsl): the views (the draw set's SCENE_VIEWS) and the hair buffers.
#define HAIR_VIEWS 0
#define HAIR_POINTS 3
#define HAIR_STRANDS 4

// The DSM build's lists (dsm/dsm_insert.glsl), raster and compute.
#define DSM_BUILD_BUCKETS 5
#define DSM_BUILD_RUNS 6
#define DSM_BUILD_STATS 7
#define DSM_BUILD_LIGHTS 8         // the depth test against the opaque casters:
#define DSM_BUILD_SHADOW_LIGHTS 9  // the lights, the shadow lights and layers and the opaque map
#define DSM_BUILD_SHADOW_LAYERS 10
#define DSM_BUILD_SHADOW_MAP 11

// The DOM build (dsm/opacity_build.comp).
#define DOM_BUILD_FIRST_DEPTHS 5
#define DOM_BUILD_LAYERS 6

// dsm/offsets.comp.
#define DSM_OFFSETS_HEADS 0
#define DSM_OFFSETS_STATS 1
#define DSM_OFFSETS_WORK 2
#define DSM_OFFSETS_BUCKETS 3

// dsm/resolve.comp.
#define DSM_RESOLVE_HEADS 0
#define DSM_RESOLVE_NODES 1
#define DSM_RESOLVE_SIDE 2
#define DSM_RESOLVE_WORK 3
#define DSM_RESOLVE_RUNS 4
#define DSM_RESOLVE_BUCKETS 5

// dsm/link.comp.
#define DSM_LINK_HEADS 0
#define DSM_LINK_NODES 1
#define DSM_LINK_UP_LINKS 2

// dsm/dsm_lookup.glsl, in every pass that looks the maps up (lighting, oit.shade, oit.hair-shadow).
#define DSM_LOOKUP_LIGHTS 8
#define DSM_LOOKUP_HEADS 9
#define DSM_LOOKUP_NODES 10
#define DSM_LOOKUP_SIDE 11

// The camera translucency build's lists (dsm/oit_insert.glsl), raster and compute.
#define OIT_BUILD_NODES 6
#define OIT_BUILD_NORMALS 7
#define OIT_BUILD_STATS 8
#define OIT_BUILD_OPAQUE_DEPTH 9
#define OIT_BUILD_BUCKETS 10
#define OIT_BUILD_TAILS 11

// dsm/oit_offsets.comp.
#define OIT_OFFSETS_BUCKETS 0
#define OIT_OFFSETS_STATS 1
#define OIT_OFFSETS_HEADS 2
#define OIT_OFFSETS_TAILS 3

// dsm/oit_sort.comp.
#define OIT_SORT_HEADS 0
#define OIT_SORT_NODES 1
#define OIT_SORT_NORMALS 2
#define OIT_SORT_STATS 3
#define OIT_SORT_LAYERS 4
#define OIT_SORT_TAILS 5
#define OIT_SORT_BUCKETS 6

// dsm/oit_shade.comp; dsm/oit_hair_shadow.comp shares the lights, shadows and hair ones.
#define OIT_SHADE_FRAME 0
#define OIT_SHADE_LIGHTS 1
#define OIT_SHADE_LAYERS 2
#define OIT_SHADE_NODES 3
#define OIT_SHADE_NORMALS 4
#define OIT_SHADE_INDIRECT 5
#define OIT_SHADE_SHADOW_PARAMS 6
#define OIT_SHADE_SHADOW_LAYERS 7
// DSM_LOOKUP_* at 8-11
#define OIT_SHADE_SHADOW_DEPTH 12
#define OIT_SHADE_SHADOW_MOMENTS 13
#define OIT_SHADE_SHADOW_LIGHTS 14
#define OIT_SHADE_HAIR_SHADOW 15
#define OIT_SHADE_HAIR_POINTS 16
#define OIT_HAIR_SHADOW_SPATIAL 17  // dsm/oit_hair_shadow.comp only
#define OIT_SHADE_SKY_IRRADIANCE 18  // the visible sky's irradiance at the pixel (names::kSkyIrradiance)

// dsm/oit_blend.comp.
#define OIT_BLEND_FRAME 0
#define OIT_BLEND_HEADS 1
#define OIT_BLEND_LAYERS 2
#define OIT_BLEND_NODES 3
#define OIT_BLEND_HDR 4

#endif
