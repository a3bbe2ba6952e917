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
// The sky behind the geometry (src/lighting/gpu_sky.h), after motion.glsl's three.
#define LIGHTING_BACKGROUND_SKY 16
// The visible sky's irradiance (names::kSkyIrradiance; a black 1x1 image without a sky).
#define LIGHTING_SKY_IRRADIANCE 17

// lighting/tonemap.comp.
#define TONEMAP_HDR 0
#define TONEMAP_LDR 1
#define TONEMAP_EXPOSURE 2

// lighting/exposure_reduce.comp and exposure_resolve.comp.
#define EXPOSURE_HDR 0
#define EXPOSURE_HISTOGRAM 1
#define EXPOSURE_STATE 2
// The luminance histogram: log2(1e-6 + luminance) in EXPOSURE_BINS equal bins over [EXPOSURE_MIN_EV,
// EXPOSURE_MAX_EV] (0.3125 EV each). The floor's 1e-6 (black) lies at -19.93 EV, inside the first bin,
// and 2^20 above middle grey's luminance outlasts photometric sunlight; what lies above is clamped
// into the last bin. Each bin keeps its count and the sum of its pixels' positions inside it in
// 1/EXPOSURE_BIN_STEPS of a bin (64 bits as two words), so a whole bin's mean is exact to 2.4e-6 EV.
#define EXPOSURE_BINS 128
#define EXPOSURE_MIN_EV (-20.0)
#define EXPOSURE_MAX_EV 20.0
#define EXPOSURE_BIN_STEPS 65536.0
// A reduce workgroup (16x16 invocations) meters a 32x32 tile, 2x2 pixels an invocation: fewer tiles
// add fewer partial histograms into the shared one.
#define EXPOSURE_TILE 32

// lighting/debug_view.comp.
#define DEBUG_VIEW_SOURCE 0
#define DEBUG_VIEW_OUT 1

#endif
