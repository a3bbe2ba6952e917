// Struct layouts shared by C++ and GLSL (std430 / std140-safe: only vec4, mat4 and 4-component
// groups). Included by C++ (namespace penumbra::gpu) and by GLSL (#include "shared/types.h").
#ifndef PENUMBRA_SHARED_TYPES_H
#define PENUMBRA_SHARED_TYPES_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace penumbra::gpu {
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
using uint = uint32_t;
#endif

// Light types (GpuLight.position.w).
#define LIGHT_DIRECTIONAL 0
#define LIGHT_SPOT 1
#define LIGHT_POINT 2

// Output selections (FrameUniforms.size.w). Radiance AOVs are tone-mapped for PNG, data AOVs not.
#define AOV_DIRECT 0
#define AOV_ALBEDO 1
#define AOV_NORMAL 2
#define AOV_DEPTH 3
#define AOV_SHADOW 4
#define AOV_FINAL 5     // direct + indirect
#define AOV_INDIRECT 6  // indirect alone (albedo / pi * gathered irradiance)
#define AOV_COUNT 7

#define ALPHA_OPAQUE 0
#define ALPHA_MASK 1
#define ALPHA_BLEND 2

#define NO_TEXTURE 0xFFFFFFFFu
#define NO_SHADOW (-1.0)

// Per-frame constants of the camera view.
struct FrameUniforms {
    mat4 viewProj;
    mat4 invViewProj;
    vec4 cameraPos;  // xyz = eye, w = far plane
    uvec4 size;      // x = width, y = height, z = light count, w = AOV
    uvec4 options;   // x = indirect irradiance image valid (GI on), yzw unused
    vec4 lens;       // x = world size of a pixel at unit distance (2 tan(fovy/2) / height), yzw unused
};

// One light as the lighting pass sees it. Units as in scene.h: directional radiance.rgb is
// irradiance (W/m^2) facing the light, spot/point radiance.rgb is intensity (W/sr).
struct GpuLight {
    vec4 position;   // xyz world position, w = type (LIGHT_*)
    vec4 direction;  // xyz direction the light travels, w = range (0 = infinite)
    vec4 radiance;   // rgb = color * intensity, w = shadow layer (NO_SHADOW = unshadowed)
    vec4 spot;       // x = cos(inner), y = cos(outer), z = normal offset in texels, w = perspective (1) or ortho (0)
    vec4 shadow;     // x = shadow texel world size (ortho) or per unit distance (perspective), yzw unused
    mat4 shadowViewProj;
};

struct GpuMaterial {
    vec4 baseColor;  // linear RGBA factor
    uvec4 info;      // x = texture index or NO_TEXTURE, y = alpha mode, z = double sided
    vec4 params;     // x = alpha cutoff
};

// Push constants of the raster passes that draw the scene.
struct DrawPush {
    uint viewIndex;  // row of the views buffer (0 = camera, 1.. = shadow layers)
    uint material;
    uint pad0;
    uint pad1;
};

// Tone-map modes: radiance is exposed and tone-mapped, colour data only sRGB-encoded, other data
// mapped linearly (value * scale + bias) so that normals and depth fit [0,1].
#define TONEMAP_ACES 0
#define TONEMAP_SRGB 1
#define TONEMAP_LINEAR 2

struct TonemapPush {
    vec4 params;  // x = exposure or scale, y = bias, z = TONEMAP_* mode, w unused
};

// Reflective shadow maps (src/rsm): one RSM layer per shadow layer that has one.
struct GpuRsmLayer {
    mat4 viewProj;
    mat4 invViewProj;
    vec4 params;  // x = texel world size (ortho) or per unit depth (perspective), y = perspective, z = light index
};

// RSM gather modes (rsm/gather.comp).
#define RSM_GATHER_FULL 0     // every full-resolution pixel, sampled pattern
#define RSM_GATHER_LOWRES 1   // one pixel per low-resolution cell, sampled pattern
#define RSM_GATHER_LIST 2     // the pixels listed by the interpolation pass, sampled pattern
#define RSM_GATHER_ALL_TEXELS 3  // every full-resolution pixel, every RSM texel (exact reference)

struct RsmPush {
    uvec4 mode;    // x = RSM_GATHER_*, y = sample count, z = layer count, w = low-resolution factor
    uvec4 sizes;   // x,y = output size (low-res or full), z = RSM resolution, w unused
    vec4 params;   // x = normal cos threshold, y = distance threshold in pixel footprints, zw unused
};

// Push constants of the RSM raster pass.
struct RsmDrawPush {
    uint viewIndex;
    uint material;
    uint light;   // index into the lights buffer
    uint layer;   // index into the RSM layers buffer
};

#ifdef __cplusplus
}  // namespace penumbra::gpu
#endif
#endif
