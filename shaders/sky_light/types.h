// The sky-light passes' binding numbers and push constants (sky_light/maps.comp, trace.comp,
// weigh.comp, filter.comp, upsample.comp), included by the GLSL and by src/sky_light: each number is
// written here only.
#ifndef PENUMBRA_SKY_LIGHT_TYPES_H
#define PENUMBRA_SKY_LIGHT_TYPES_H

#include "shared/types.h"

#ifdef __cplusplus
namespace penumbra::gpu {
#endif

// maps.comp
#define SKY_MAPS_FRAME 0
#define SKY_MAPS_GBUFFER_NORMAL 1
#define SKY_MAPS_GBUFFER_DEPTH 2
#define SKY_MAPS_DEPTH 3       // R32_SFLOAT array: layer k the depth map seen from sky direction k
#define SKY_MAPS_OUT 4         // rgb: the share of the sky's radiance a traced receiver sees (as weigh.comp's)
#define SKY_MAPS_SKY_RADIANCE 5  // the sky's radiance, equirectangular (names::kSkyRadiance)
#define SKY_MAPS_DIRECTIONS 6  // SkyMapDirection[]: each map's direction and view

// trace.comp
#define SKY_TRACE_FRAME 0
#define SKY_TRACE_GBUFFER_NORMAL 1
#define SKY_TRACE_GBUFFER_DEPTH 2
#define SKY_TRACE_OCCUPANCY 3
#define SKY_TRACE_OUT 4  // rg32ui: bit k of r set where ray k is clear (all bits: no occlusion); g: the
                         // receiver's depth bits

// weigh.comp
#define SKY_WEIGH_FRAME 0
#define SKY_WEIGH_GBUFFER_NORMAL 1
#define SKY_WEIGH_GBUFFER_DEPTH 2
#define SKY_WEIGH_CLEAR_RAYS 3
#define SKY_WEIGH_OUT 4  // rgb: the share of the sky's radiance a traced receiver sees, per channel
#define SKY_WEIGH_SKY_RADIANCE 5  // the sky's radiance, equirectangular (names::kSkyRadiance)

// filter.comp
#define SKY_FILTER_FRAME 0
#define SKY_FILTER_GBUFFER_NORMAL 1
#define SKY_FILTER_GBUFFER_DEPTH 2
#define SKY_FILTER_SHARE 3
#define SKY_FILTER_OUT 4  // rgb: the share averaged over the receiver's surface around it

// upsample.comp
#define SKY_UPSAMPLE_FRAME 0
#define SKY_UPSAMPLE_GBUFFER_NORMAL 1
#define SKY_UPSAMPLE_GBUFFER_DEPTH 2
#define SKY_UPSAMPLE_SHARE 3
#define SKY_UPSAMPLE_OUT 4  // rgb: the visible sky's irradiance at every pixel (names::kSkyIrradiance)
#define SKY_UPSAMPLE_SKY_SH 5  // the sky's SH radiance (names::kSkySh)

// Rays of one traced receiver share a rotation with those SKY_TILE apart: a SKY_TILE^2 block holds
// every rotation, which the filter averages back together.
#define SKY_TILE 4
#define SKY_MAX_RAYS 32  // the bits of a clear-ray mask
#define SKY_MAX_MAPS 256  // --sky-maps' upper bound (maps.comp keeps each direction's radiance in shared memory)
#define SKY_TRACE_EVERY_TEXEL 0xFFFFFFFFu  // SkyLightPush.tracePhase: no subset

// One direction of the sky maps (maps.comp): towards the sky, and the orthographic view of the
// scene from it that its depth map was drawn with.
struct SkyMapDirection {
    mat4 viewProj;   // world -> clip (x, y in [-1, 1] across the map, z the stored depth)
    vec3 direction;  // unit, towards the sky (y > 0)
    float pad;
};

// Every pass's push constants: the walk's parameters.
struct SkyLightPush {
    uint rays;          // trace, weigh: rays per receiver (0: every pixel sees the whole sky)
    float startOffset;  // trace: voxels off the surface, along its normal, where the rays start
    uint filterRadius;  // filter: traced receivers either side
    uint traceStep;     // camera pixels between traced receivers, per axis
    // trace: SKY_TRACE_EVERY_TEXEL, or 0 to 3: texel (phase & 1, phase >> 1) of each 2x2 block and
    // those whose receiver changed (geometry moving under a still view is traced over four frames)
    uint tracePhase;
    uint mapCount;      // maps: directions, one depth map each (0: every pixel sees the whole sky)
    uint mapResolution;  // maps: texels per side
    float mapOffset;    // maps: world distance off the surface, along its normal, where a receiver looks up
};

#ifdef __cplusplus
static_assert(sizeof(SkyMapDirection) == 80 && offsetof(SkyMapDirection, direction) == 64);
static_assert(sizeof(SkyLightPush) == 32 && offsetof(SkyLightPush, tracePhase) == 16 && offsetof(SkyLightPush, rays) == 0 &&
              offsetof(SkyLightPush, traceStep) == 12 && offsetof(SkyLightPush, mapCount) == 20 &&
              offsetof(SkyLightPush, mapResolution) == 24 && offsetof(SkyLightPush, mapOffset) == 28);
}  // namespace penumbra::gpu
#endif
#endif
