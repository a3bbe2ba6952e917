// Shadow maps (src/shadow): the structs and constants its passes share between C++ and GLSL,
// laid out by the rules of shared/types.h, which includes this file (its includers see them all).
#ifndef PENUMBRA_SHADOW_TYPES_H
#define PENUMBRA_SHADOW_TYPES_H

#include "shared/types.h"

#ifdef __cplusplus
namespace penumbra::gpu {
#endif

// Filters (GpuShadowLight.filterMode; the same values as penumbra::ShadowFilter in scene/scene.h).
#define SHADOW_FILTER_HARD 1
#define SHADOW_FILTER_PCF 2
#define SHADOW_FILTER_PCSS 3
#define SHADOW_FILTER_VSM 4
#define SHADOW_FILTER_EVSM 5
#define SHADOW_FILTER_MSM 6
// How a shadowed light's layers cover space (GpuShadowLight.kind).
#define SHADOW_KIND_SINGLE 0      // one perspective layer (spot)
#define SHADOW_KIND_CASCADES 1    // directional: orthographic cascades, chosen by view depth
#define SHADOW_KIND_CUBE 2        // point: 6 perspective faces +x, -x, +y, -y, +z, -z
#define SHADOW_KIND_PARABOLOID 3  // point: 2 paraboloid hemispheres around +axis and -axis
// Projection of one layer (GpuShadowLayer.projection).
#define SHADOW_PROJ_ORTHO 0
#define SHADOW_PROJ_PERSPECTIVE 1
#define SHADOW_PROJ_PARABOLOID 2
#define SHADOW_NO_MOMENTS 0xFFFFFFFFu

// One shadowed light; GpuLight.shadowIndex is its index here and its layer in the shadow mask.
struct GpuShadowLight {
    uint firstLayer;
    uint layerCount;
    uint kind;             // SHADOW_KIND_*
    uint filterMode;       // SHADOW_FILTER_*
    float normalOffset;    // texels
    float penumbraScale;   // PCSS: the light's diameter (spot and point lights), 2 tan(angular radius)
                           // (directional ones)
    float pad0;
    float pad1;
};

// One layer of the shadow-map array.
struct GpuShadowLayer {
    mat4 viewProj;      // world -> clip; paraboloid layers: world -> the hemisphere's view space
    float texelSize;    // texel world size (ortho) or per unit distance (perspective; paraboloid: on its axis)
    float zNear;        // view distances of depth 0 and 1
    float zFar;
    float discScale;    // paraboloid layers: the disc's scale
    float splitNear;    // cascades: the near and far split (camera view depths)
    float splitFar;
    float pad0;
    float pad1;
    uint projection;    // SHADOW_PROJ_*
    uint momentLayer;   // or SHADOW_NO_MOMENTS
    uint momentFilter;  // SHADOW_FILTER_* of the moments stored there
    uint pad2;
};

// What the moment filters (VSM, EVSM, MSM) read beside the moments (shadow/moments.glsl).
struct GpuMomentParams {
    float bleedReduction;  // light-bleeding reduction
    float evsmPositive;    // EVSM exponents
    float evsmNegative;
    float msmBias;
};

struct GpuShadowParams {
    float pcfRadius;       // texels
    float pcssMaxRadius;   // PCSS max search radius (texels)
    float cascadeBlend;    // cascade blend band (fraction of a cascade)
    float pad0;
    GpuMomentParams moments;
    uint resolution;       // shadow-map resolution
    uint blurRadius;       // moment blur radius (texels)
    uint shadowedLights;   // shadowed light count
    uint pad1;
    vec4 poisson[16];  // 32 points of a progressive Poisson-disc set in the unit disc (xy, zw):
                       // any prefix is well spread, so PCF takes the first 16 and PCSS all 32
};

// Push constants of the shadow raster passes (layered: instance i draws layer firstLayer + i with
// views row viewIndex + i). Starts like DrawPush so that shared fragment code reads `material`.
struct ShadowDrawPush {
    uint viewIndex;
    uint material;
    uint firstLayer;
    uint layerCount;    // instances of a draw = scene instances x layers (layer fastest)
    uint triangleBase;  // the draw's first triangle within its mesh (DrawPush.triangleBase)
    uint pad0;
    uint pad1;
    uint pad2;
    // Paraboloid layers (shadow/paraboloid.*): near and far, disc scale, the largest angle a
    // tessellated edge may span (radians).
    float paraboloidNear;
    float paraboloidFar;
    float paraboloidDiscScale;
    float maxEdgeAngle;
};

#ifdef __cplusplus
static_assert(sizeof(ShadowDrawPush) == 48 && sizeof(GpuShadowParams) == 304 && sizeof(GpuShadowLayer) == 112);
static_assert(sizeof(GpuShadowLight) == 32 && offsetof(GpuShadowLight, normalOffset) == 16);
static_assert(offsetof(GpuShadowLayer, texelSize) == 64 && offsetof(GpuShadowLayer, splitNear) == 80 &&
              offsetof(GpuShadowLayer, projection) == 96);
static_assert(sizeof(GpuMomentParams) == 16 && offsetof(GpuShadowParams, moments) == 16 &&
              offsetof(GpuShadowParams, resolution) == 32 && offsetof(GpuShadowParams, poisson) == 48);
static_assert(offsetof(ShadowDrawPush, triangleBase) == 16 && offsetof(ShadowDrawPush, paraboloidNear) == 32);
}  // namespace penumbra::gpu
#endif
#endif
