// Binding numbers of the lighting pass's set 0 (lighting/lighting.comp), included by the GLSL and by
// src/lighting/lighting_pass.cpp: each number is written here only.
#ifndef PENUMBRA_LIGHTING_BINDINGS_H
#define PENUMBRA_LIGHTING_BINDINGS_H

#include "dsm/bindings.h"

#define LIGHTING_FRAME 0
#define LIGHTING_LIGHTS 1
#define LIGHTING_GBUFFER_ALBEDO 2
#define LIGHTING_GBUFFER_NORMAL 3
#define LIGHTING_GBUFFER_DEPTH 4
#define LIGHTING_SHADOW_MASK 5
#define LIGHTING_HDR 6
#define LIGHTING_INDIRECT 7
// dsm/dsm_lookup.glsl's four buffers (lights, heads, nodes, side lists), numbered there.
#define LIGHTING_DSM_LIGHTS DSM_LOOKUP_LIGHTS
#define LIGHTING_DSM_HEADS DSM_LOOKUP_HEADS
#define LIGHTING_DSM_NODES DSM_LOOKUP_NODES
#define LIGHTING_DSM_SIDE DSM_LOOKUP_SIDE
#define LIGHTING_PROBE 12
// core/motion.glsl's three (visibility IDs, drawn triangles, instances) from here on.
#define LIGHTING_MOTION_FIRST 13
// The sky behind the geometry (src/lighting/sky_background.h), after motion.glsl's three.
#define LIGHTING_BACKGROUND_SKY 16
// The visible sky's irradiance (names::kSkyIrradiance; a black 1x1 image without a sky).
#define LIGHTING_SKY_IRRADIANCE 17

// lighting/tonemap.comp.
#define TONEMAP_HDR 0
#define TONEMAP_LDR 1
#define TONEMAP_EXPOSURE 2

// lighting/exposure_reduce.comp and exposure_resolve.comp.
#define EXPOSURE_HDR 0
#define EXPOSURE_PARTIALS 1
#define EXPOSURE_STATE 2

// lighting/debug_view.comp.
#define DEBUG_VIEW_SOURCE 0
#define DEBUG_VIEW_OUT 1

#endif
