// Struct layouts shared by C++ and GLSL (std430 / std140-safe: mat4, vec4, a vec3 always followed
// by a 4-byte scalar, a vec2 by a vec2 or two scalars, and scalars in groups of four). Included by
// C++ (namespace penumbra::gpu) and by GLSL (#include "shared/types.h").
#ifndef PENUMBRA_SHARED_TYPES_H
#define PENUMBRA_SHARED_TYPES_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
namespace penumbra::gpu {
using ivec2 = glm::ivec2;
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uvec3 = glm::uvec3;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
using uint = uint32_t;
#endif

// Light types (GpuLight.type).
#define LIGHT_DIRECTIONAL 0
#define LIGHT_SPOT 1
#define LIGHT_POINT 2

// Output selections (FrameUniforms.aov). Radiance AOVs are tone-mapped for PNG, data AOVs not.
#define AOV_DIRECT 0
#define AOV_ALBEDO 1
#define AOV_NORMAL 2
#define AOV_DEPTH 3
#define AOV_SHADOW 4
#define AOV_FINAL 5     // direct + indirect
#define AOV_INDIRECT 6  // indirect alone (albedo / pi * gathered irradiance)
#define AOV_LPV_SLICE 7  // debug: one slice of the accumulated light volume (raw, no albedo)
#define AOV_GV_SLICE 8   // debug: the same slice of the geometry (blocking) volume
#define AOV_CASCADE 9    // debug: shadow layer of the first shadowed light (cascade, cube face, hemisphere)
#define AOV_TRANSMITTANCE 10  // deep shadow map transmittance of the first light with one (1 = nothing translucent)
#define AOV_DSM_LISTS 11      // debug: list length per texel of the first deep shadow map (its map over the image)
#define AOV_RSM_DEPTH 12   // debug: layer --aov-layer of the RSM's depth (letterboxed square)
#define AOV_RSM_NORMAL 13  // debug: the RSM's normal, n * 0.5 + 0.5
#define AOV_RSM_FLUX 14    // debug: the RSM's flux (exposed and tone-mapped like radiance)
#define AOV_SHADOW_MAP 15  // debug: layer --aov-layer of the shadow-map array's depth
#define AOV_VELOCITY 16    // screen-space motion since the previous frame, pixels (xy: now minus then)
#define AOV_SKY 17         // debug: the visible sky's irradiance at each surface (src/sky_light; 0 without a sky)
#define AOV_COUNT 18

#define ALPHA_OPAQUE 0
#define ALPHA_MASK 1
#define ALPHA_BLEND 2

#define NO_TEXTURE 0xFFFFFFFFu
// Slots of the material texture table (core/material_textures.glsl, SceneGpu): with a pass's own
// sampled images within lavapipe's 32 per stage (SceneGpu::checkTextureTable says why).
#define MATERIAL_TEXTURE_SLOTS 28
// A material's texture handle: slot | layer << TEXTURE_LAYER_SHIFT (each slot is a 2D array of one size).
#define TEXTURE_LAYER_SHIFT 5
#define TEXTURE_SLOT_MASK 31u
#define NO_SHADOW (-1)  // GpuLight.shadowIndex of an unshadowed light

// Per-frame constants of the camera view.
struct FrameUniforms {
    mat4 viewProj;
    mat4 invViewProj;
    mat4 previousViewProj;  // the previous frame's viewProj (velocity); this frame's on the first
    mat4 reprojection;      // previousViewProj * inverse(viewProj), in double precision: this frame's clip
                            // position -> the previous frame's, for points that did not move (exact when
                            // the camera stood still, which a float round trip through the world is not)
    vec3 eye;
    float farPlane;
    uint width;
    uint height;
    uint lightCount;
    uint aov;            // AOV_*
    uint giValid;        // 1: the indirect irradiance image is valid (GI on)
    uint visibilityIds;  // 1: visibility IDs valid (the camera's visibility path: velocity follows moving instances)
    uint probeX;         // the probed pixel (PROBE_OFF: none)
    uint probeY;
    float pixelSpread;   // world size of a pixel at unit distance (2 tan(fovy/2) / height)
    uint pad0;
    uint pad1;
    uint pad2;
};

#define PROBE_OFF 0xFFFFFFFFu

// Every AOV at one pixel (the viewer's pixel probe), written by lighting/lighting.comp for the pixel
// FrameUniforms.probeX, probeY name, as the AOV images would hold them.
struct PixelProbe {
    vec3 finalRadiance;         // direct + indirect
    uint surface;               // 1 on a surface, 0 on the background
    vec3 direct;                // direct radiance
    float eyeDistance;          // distance to the eye (the depth AOV)
    vec3 indirect;              // indirect radiance (albedo / pi * irradiance)
    float shadowVisibility;     // the first shadowed light's visibility (the shadow AOV)
    vec3 irradiance;            // gathered indirect irradiance (0 with --gi none)
    float shadowLayer;          // the first shadowed light's layer code there (-1: none)
    vec3 albedo;
    float transmittance;        // the first deep shadow map's transmittance (1: nothing translucent)
    vec3 normal;                // shading normal (hair: tangent)
    float shadingModel;         // SHADING_* (the G-buffer normal's w)
    vec3 position;              // world position
    uint pad0;
    vec2 velocity;              // the velocity AOV (pixels)
    uint pad1;
    uint pad2;
};

// One light as the lighting pass sees it. Units as in scene.h: directional radiance.rgb is
// irradiance (W/m^2) facing the light, spot/point radiance.rgb is intensity (W/sr).
struct GpuLight {
    vec3 position;    // world
    uint type;        // LIGHT_*
    vec3 direction;   // the direction the light travels
    float range;      // 0 = infinite
    vec3 radiance;    // color * intensity
    int shadowIndex;  // GpuShadowLight and shadow-mask layer (NO_SHADOW = unshadowed)
    float cosInner;   // spot cone
    float cosOuter;
    // The light's first shadow layer, for passes that want one view of the light (the full layer
    // list with cascades and cube faces is the shadow-layer table, src/shadow):
    float normalOffset;     // texels
    uint perspective;       // 1: perspective, 0: orthographic
    float shadowTexelSize;  // texel world size (ortho) or per unit distance (perspective)
    uint pad0;
    uint pad1;
    uint pad2;
    mat4 shadowViewProj;
};

struct GpuMaterial {
    vec4 baseColor;     // linear RGBA factor
    uint texture;       // texture handle (slot | layer << TEXTURE_LAYER_SHIFT) or NO_TEXTURE
    uint alphaMode;     // ALPHA_*
    uint doubleSided;   // 1: both faces drawn
    uint pad0;
    float alphaCutoff;  // ALPHA_MASK: alpha below it is cut out
    float pad1;
    float pad2;
    float pad3;
};

// One drawn instance of a mesh (Scene::instances): the one place its transform lives. A draw covers a
// run of instances of one mesh: gl_InstanceIndex is the instance (layered passes: gl_BaseInstance +
// (gl_InstanceIndex - gl_BaseInstance) / layers); compute passes index it per triangle.
struct GpuInstance {
    mat4 model;   // object -> world
    mat4 normal;  // inverse transpose of model's upper 3x3 (columns 0-2)
    mat4 toPrevious;  // world now -> world in the previous frame (previous model * inverse model): velocity
    uint mirrored;    // 1 when model mirrors (negative determinant: fronts flip)
    uint firstDrawnTriangle;  // the drawn-triangle index of the mesh's first triangle
                              // (SceneGpu::drawnTriangles: visibility IDs)
    uint pad0;
    uint pad1;
};

// Push constants of the raster passes that draw the scene.
struct DrawPush {
    uint viewIndex;  // row of the views buffer (0 = camera, 1.. = shadow layers)
    uint material;
    uint pad0;
    uint triangleBase;  // the draw's first triangle within its mesh: visibility IDs are the instance's
                        // drawn-triangle base + this + gl_PrimitiveID + 1 (core/visibility.glsl)
};

// Tone-map modes: radiance is exposed and tone-mapped, colour data only sRGB-encoded, other data
// mapped linearly (value * scale + bias) so that normals and depth fit [0,1].
#define TONEMAP_ACES 0
#define TONEMAP_SRGB 1
#define TONEMAP_LINEAR 2

// lighting/debug_view.comp.
struct DebugViewPush {
    uint aov;    // AOV_RSM_* or AOV_SHADOW_MAP
    uint layer;  // the source's layer
    uint pad0;
    uint pad1;
};

struct TonemapPush {
    float scale;  // the exposure (radiance) or the linear scale
    float bias;   // TONEMAP_LINEAR: added after the scale
    uint mode;    // TONEMAP_*
    uint autoExposure;  // 1: scale also multiplies AutoExposureState.exposure (lighting/auto_exposure.h)
};

// The auto exposure's state across frames (lighting/exposure_resolve.comp).
struct AutoExposureState {
    float adaptedLog;  // log of the adapted exposure
    float exposure;    // exp(adaptedLog): what the tone mapper multiplies by
    float logAverage;  // this frame's mean log luminance of the metered geometry pixels
    uint valid;        // 0 until a frame had geometry
};

struct AutoExposurePush {
    float rate;          // the adaptation's step, 1 - exp(-dt / tau); 1: snap
    float lowFraction;   // the metered window of the geometry pixels ranked by luminance, in [0, 1]
    float highFraction;  // (`--exposure-percentiles` / 100)
    uint pad;
};

// Reflective shadow maps (src/rsm): one RSM layer per shadow layer that has one.
struct GpuRsmLayer {
    mat4 viewProj;
    mat4 invViewProj;
    float texelSize;    // texel world size (orthographic) or per unit depth (perspective)
    uint perspective;   // 1: a perspective layer (spot, cube face), 0: orthographic
    uint light;         // the layer's light (index into the lights)
    uint cascade;       // cascade index + 1 (0: not a cascade)
    uint lastCascade;   // 1 on a light's last cascade
    float radiusScale;  // r_max scale
    uint pad0;
    uint pad1;
};

// RSM gather modes (rsm/gather.comp).
#define RSM_GATHER_FULL 0     // every full-resolution pixel, sampled pattern
#define RSM_GATHER_LOWRES 1   // one pixel per low-resolution cell, sampled pattern
#define RSM_GATHER_LIST 2     // the pixels listed by the interpolation pass, sampled pattern
#define RSM_GATHER_ALL_TEXELS 3  // every full-resolution pixel, every RSM texel (exact reference)
#define RSM_GATHER_GRADIENT 4  // last frame's gradient samples again, with their pattern and this frame's RSM

// How the gather tests whether a VPL sees its receiver (--rsm-visibility).
#define RSM_VISIBILITY_NONE 0    // every VPL lights every receiver it faces
#define RSM_VISIBILITY_DEPTH 1   // far samples: two points of the segment against the RSM's depth
#define RSM_VISIBILITY_VOXELS 2  // every sample: the segment marched through the occupancy volume
#define RSM_VISIBILITY_VIEWS 3   // every sample: points of the segment against the RSM's and the camera's depth

struct RsmPush {
    uint mode;                // RSM_GATHER_*
    uint sampleCount;
    uint layerCount;
    uint lowResFactor;
    uint width;               // output size (the low-resolution grid's or the full image's)
    uint height;
    uint rsmResolution;
    uint bilinearVpls;        // 1: VPLs interpolated bilinearly
    float normalThreshold;    // normal cos threshold (interpolation)
    float distanceThreshold;  // in pixel footprints (interpolation)
    float radius;             // r_max
    uint frameSeed;           // 0: the pattern of every frame alike; else mixed into each receiver's (temporal GI)
    uint visibility;          // RSM_VISIBILITY_*
    uint visibilityRays;      // samples a pixel tests through the occupancy volume
    uint paperWeights;        // 1: the paper's single disc and xi1^2 weights (else the mixture)
    uint lanesPerReceiver;
    uint farByFlux;           // 1: the far half of the samples drawn by flux (rsm/flux_draw.comp)
    uint shiftedRadii;        // 1: radii shifted per receiver (pipelines with RSM_SHIFTED_RADII)
    uint visibilityPoints;    // points a segment is tested at (RSM_VISIBILITY_VIEWS)
    // RSM_GATHER_LOWRES: 1 + which cell of each 2x2 block keeps its receiver as a gradient sample
    // (0: none kept); RSM_GATHER_GRADIENT: the gradient image's texel in low-resolution cells (2).
    uint gradientPhase;
};

// A receiver of the low-resolution RSM gather kept for the next frame's temporal gradient (Schied et
// al. 2018): the next frame gathers at it again with this frame's pattern and its own RSM, so the
// difference of the two luminances is the change of the light alone, free of the pattern's noise.
// One per 2x2 block of low-resolution cells.
struct GpuGradientSample {
    vec3 position;    // world space
    float luminance;  // of its irradiance this frame; < 0: no receiver
    vec3 normal;      // as gathered (facing the eye), or a strand's tangent
    uint hair;        // 1: a hair strand
};

// The flux-drawn VPLs of --rsm-far flux (rsm/flux_draw.comp), per layer a block of RSM_FLUX_BLOCK
// uvec4: the layer's total flux luminance (x, float bits); then RSM_FLUX_ENTRIES texels drawn with
// probability proportional to their flux luminance, stratified in the order of a Hilbert curve over
// the map, each as two uvec4 that share one 32-byte sector: its packed VPL (rsm/resolve.comp's
// texel) and its texel (x | y << 16, in x).
#define RSM_FLUX_ENTRIES 16384u
#define RSM_FLUX_BLOCK (2u + 2u * RSM_FLUX_ENTRIES)

// Push constants of rsm/flux_sums.comp and rsm/flux_draw.comp.
struct RsmFluxPush {
    uint rsmResolution;
    uint layerCount;
    uint curve;  // n: the Hilbert curve's side (n runs of n texels per layer)
    uint step;   // flux_sums.comp: 0 sums along the runs, 1 the runs' totals
    uint seed;   // flux_draw.comp: the draws' jitter
    uint pad0;
    uint pad1;
    uint pad2;
};

// temporal_gi/accumulate.comp: the indirect irradiance blended into its history (src/temporal_gi).
struct GiAccumulatePush {
    float minWeight;     // the least weight of a new frame: a history spans at most 1 / minWeight frames
    float changeWeight;  // the least weight of this frame, from how much the lights changed since the last
    uint historyValid;   // 1: the history holds the previous frame
    uint changePixels;   // pixels per texel of the detected change (names::kGiChange); 0: none this frame
    float lagTolerance;  // a detected change of c per frame weighs the new frame c / lagTolerance
    uint pad0;
    uint pad1;
    uint pad2;
};

// temporal_gi/filter.comp: one iteration of the edge-aware a-trous filter.
struct GiFilterPush {
    uint step;              // tap spacing in pixels: 1, 2, 4, ... (iteration k: 2^k)
    uint firstIteration;    // 1: read the accumulation (and its moments), else the previous iteration
    float luminanceSigma;   // luminance edge stop: differences beyond this many standard deviations fade out
    uint pad0;
};

// Push constants of the RSM resolve (rsm/resolve.comp): RSM texels from the shadow pass's visibility IDs.
struct RsmResolvePush {
    uint rsmResolution;
    uint idResolution;  // resolution of the ID layers (the shadow map's)
    uint pad0;
    uint pad1;
};

// Push constants of the camera's visibility resolve (lighting/visibility_resolve.comp).
struct VisibilityResolvePush {
    uint width;   // image size
    uint height;
    uint pad0;
    uint pad1;
};

// Light propagation volumes (src/lpv). Volumes are buffers: light volume c, channel ch (R, G, B) is
// vec4 SH coefficients per cell at ((c * 3 + ch) * cells + cell); the geometry volume is one vec4
// per cell at (c * cells + cell), its cell k sitting at the light cells' corner k (half a cell off).
#define LPV_MAX_CASCADES 4
#define LPV_FACE_COLUMNS 4  // lpv/face_transmittance.comp: segments per side of a cell face
#define LPV_CHANGE_BLOCK 8  // lpv/gradient.comp: one change texel (core/names.h GiChange) per 8x8 pixels

struct GpuLpvCascade {
    vec3 origin;     // world position of the grid's min corner
    float cellSize;  // world
};

// A virtual point light after RSM down-sampling.
struct GpuVpl {
    vec3 position;
    uint exists;  // 1: a VPL (0: its RSM cell held no surface)
    vec3 normal;  // unit
    float area;   // surfel area (world, on the surface)
    vec3 flux;    // reflected flux
    uint pad0;
};

struct LpvPush {
    uint resolution;        // cells per axis
    uint cascadeCount;
    uint iteration;         // propagate.comp: this step (0: the first)
    uint farFromIteration;  // propagate.comp: the step from which a coarser cascade's light sums as far
    uint vplCount;
    uint rsmResolution;     // the RSM source's resolution
    uint vplResolution;     // the down-sampled resolution
    uint layerCount;
    uint occlusion;         // 1: geometry blocks the light
    float blendCells;       // gather blend band in cells
    uint cameraGeometryStep;  // G-buffer injection step (pixels)
    uint voxelFaces;        // 1: occlusion from the occupancy volume's faces, 0: from the geometry volume
    uint sliceAxis;         // gather.comp's slice views
    uint sliceIndex;
    uint pad0;
    uint pad1;
    GpuLpvCascade cascades[LPV_MAX_CASCADES];
};

#ifdef __cplusplus
// The layouts the shaders see (std430, push constants likewise): scalars pack in fours after a mat4
// or vec4, a struct rounds up to 16 bytes. tests/spirv_reflection_test.cpp compares every member
// with the compiled SPIR-V; these catch a C++-only edit at compile time.
static_assert(sizeof(GpuRsmLayer) == 160 && offsetof(GpuRsmLayer, texelSize) == 128 &&
              offsetof(GpuRsmLayer, cascade) == 140 && offsetof(GpuRsmLayer, radiusScale) == 148);
static_assert(sizeof(RsmPush) == 80 && offsetof(RsmPush, width) == 16 && offsetof(RsmPush, normalThreshold) == 32 &&
              offsetof(RsmPush, visibility) == 48 && offsetof(RsmPush, farByFlux) == 64 &&
              offsetof(RsmPush, visibilityPoints) == 72 && offsetof(RsmPush, gradientPhase) == 76);
static_assert(sizeof(GpuGradientSample) == 32 && offsetof(GpuGradientSample, luminance) == 12 &&
              offsetof(GpuGradientSample, normal) == 16 && offsetof(GpuGradientSample, hair) == 28);
static_assert(sizeof(RsmFluxPush) == 32 && offsetof(RsmFluxPush, seed) == 16);
static_assert(sizeof(RsmResolvePush) == 16 && offsetof(RsmResolvePush, idResolution) == 4);
static_assert(sizeof(LpvPush) == 128 && offsetof(LpvPush, vplCount) == 16 && offsetof(LpvPush, occlusion) == 32 &&
              offsetof(LpvPush, sliceAxis) == 48 && offsetof(LpvPush, cascades) == 64);
static_assert(sizeof(TonemapPush) == 16 && offsetof(TonemapPush, mode) == 8);
static_assert(sizeof(AutoExposureState) == 16 && sizeof(AutoExposurePush) == 16);
static_assert(sizeof(GiAccumulatePush) == 32 && offsetof(GiAccumulatePush, historyValid) == 8 &&
              offsetof(GiAccumulatePush, lagTolerance) == 16);
static_assert(sizeof(GiFilterPush) == 16 && offsetof(GiFilterPush, luminanceSigma) == 8);
static_assert(offsetof(FrameUniforms, eye) == 256 && offsetof(FrameUniforms, farPlane) == 268 &&
              offsetof(FrameUniforms, width) == 272 && offsetof(FrameUniforms, giValid) == 288 &&
              offsetof(FrameUniforms, pixelSpread) == 304);
static_assert(offsetof(GpuLight, type) == 12 && offsetof(GpuLight, direction) == 16 && offsetof(GpuLight, range) == 28 &&
              offsetof(GpuLight, radiance) == 32 && offsetof(GpuLight, shadowIndex) == 44 &&
              offsetof(GpuLight, cosInner) == 48 && offsetof(GpuLight, shadowTexelSize) == 64 &&
              offsetof(GpuLight, shadowViewProj) == 80);
static_assert(sizeof(PixelProbe) == 128 && offsetof(PixelProbe, finalRadiance) == 0 &&
              offsetof(PixelProbe, surface) == 12 && offsetof(PixelProbe, direct) == 16 &&
              offsetof(PixelProbe, eyeDistance) == 28 && offsetof(PixelProbe, indirect) == 32 &&
              offsetof(PixelProbe, shadowVisibility) == 44 && offsetof(PixelProbe, irradiance) == 48 &&
              offsetof(PixelProbe, shadowLayer) == 60 && offsetof(PixelProbe, albedo) == 64 &&
              offsetof(PixelProbe, transmittance) == 76 && offsetof(PixelProbe, normal) == 80 &&
              offsetof(PixelProbe, shadingModel) == 92 && offsetof(PixelProbe, position) == 96 &&
              offsetof(PixelProbe, pad0) == 108 && offsetof(PixelProbe, velocity) == 112 &&
              offsetof(PixelProbe, pad1) == 120 && offsetof(PixelProbe, pad2) == 124);
static_assert(offsetof(GpuVpl, position) == 0 && offsetof(GpuVpl, exists) == 12 && offsetof(GpuVpl, normal) == 16 &&
              offsetof(GpuVpl, area) == 28 && offsetof(GpuVpl, flux) == 32 && offsetof(GpuVpl, pad0) == 44);
static_assert(sizeof(GpuLpvCascade) == 16 && offsetof(GpuLpvCascade, origin) == 0 &&
              offsetof(GpuLpvCascade, cellSize) == 12);
static_assert(sizeof(GpuVpl) == 48 && sizeof(GpuLight) == 144 && sizeof(FrameUniforms) == 320 &&
              sizeof(GpuInstance) == 208 && sizeof(DrawPush) == 16);
static_assert(sizeof(GpuMaterial) == 48 && offsetof(GpuMaterial, texture) == 16 && offsetof(GpuMaterial, alphaCutoff) == 32);
static_assert(offsetof(GpuInstance, mirrored) == 192 && offsetof(GpuInstance, firstDrawnTriangle) == 196);
static_assert(sizeof(DebugViewPush) == 16 && sizeof(VisibilityResolvePush) == 16);
}  // namespace penumbra::gpu
#endif

// Each module's own structs (after the shared ones, which they use).
#include "shadow/types.h"
#include "dsm/types.h"
#include "raster/types.h"
#include "voxel/types.h"

#endif
