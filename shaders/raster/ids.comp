#version 460
// The compute rasterizer's layers with visibility IDs (src/raster), after the tile pass: each texel's
// 64-bit depth << 32 | ID splits into the depth buffer (the resolve copies it into the shadow map
// with the other layers) and the ID image (0 where nothing was drawn, render/visibility.glsl).
// One thread per texel, z = row of the layer table (rows without IDs return at once).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#include "shared/types.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, std430) writeonly buffer Depth { uint depthBits[]; };
layout(set = 0, binding = 1, std430) readonly buffer DepthIds { uint64_t depthIds[]; };
layout(set = 0, binding = 2, std430) readonly buffer Layers { RasterLayer rasterLayers[]; };
layout(set = 0, binding = 3, r32ui) uniform writeonly uimage2DArray ids;
layout(push_constant) uniform Push { RasterPush push; };

// Cleared to just above 1.0 (clamped depths never reach it): the hardware's test is LESS_OR_EQUAL
// against 1.0, so a triangle at exactly the far plane writes its ID there too.
const uint kFar = 0x3F800000u;  // 1.0

void main() {
    const uint res = push.target.x;
    const uvec2 p = gl_GlobalInvocationID.xy;
    const RasterLayer row = rasterLayers[gl_GlobalInvocationID.z];
    if (row.info.w == 0u || any(greaterThanEqual(p, uvec2(res)))) return;
    const uint idLayer = row.info.w - 1u;
    const uint64_t v = depthIds[(idLayer * res + p.y) * res + p.x];
    const uint bits = uint(v >> 32);
    depthBits[(row.info.y * res + p.y) * res + p.x] = min(bits, kFar);
    imageStore(ids, ivec3(p, idLayer), uvec4(bits > kFar ? 0u : uint(v), 0u, 0u, 0u));
}
