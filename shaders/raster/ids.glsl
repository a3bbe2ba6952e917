// The body of raster/ids*.comp (see raster/ids.comp). RASTER_ID_IMAGE_2D: one 2D layer (the camera's
// visibility buffer); RASTER_DEPTH_IMAGE: depth goes straight into the R32_SFLOAT target (no store
// pass after it), else into the depth buffer (which a copy then takes into a D32_SFLOAT target).
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 1, std430) readonly buffer DepthIds { uint64_t depthIds[]; };
layout(set = 0, binding = 2, std430) readonly buffer Layers { RasterLayer rasterLayers[]; };
#ifdef RASTER_ID_IMAGE_2D
layout(set = 0, binding = 3, r32ui) uniform writeonly uimage2D ids;
#define ID_TEXEL(p, layer) ivec2(p)
#else
layout(set = 0, binding = 3, r32ui) uniform writeonly uimage2DArray ids;
#define ID_TEXEL(p, layer) ivec3(p, layer)
#endif
#ifdef RASTER_DEPTH_IMAGE
#ifdef RASTER_ID_IMAGE_2D
layout(set = 0, binding = 0, r32f) uniform writeonly image2D depthMap;
#else
layout(set = 0, binding = 0, r32f) uniform writeonly image2DArray depthMap;
#endif
#define STORE_DEPTH(p, layer, bits) imageStore(depthMap, ID_TEXEL(p, layer), vec4(uintBitsToFloat(bits)))
#else
layout(set = 0, binding = 0, std430) writeonly buffer Depth { uint depthBits[]; };
#define STORE_DEPTH(p, layer, bits) depthBits[((layer) * size.y + (p).y) * size.x + (p).x] = (bits)
#endif
layout(push_constant) uniform Push { RasterPush push; };

// Cleared to just above 1.0 (clamped depths never reach it): the hardware's test is LESS_OR_EQUAL
// against 1.0, so a triangle at exactly the far plane writes its ID there too.
const uint kFar = 0x3F800000u;  // 1.0

void main() {
    const uvec2 size = uvec2(push.target.x, push.capacity.w);
    const uvec2 p = gl_GlobalInvocationID.xy;
    const RasterLayer row = rasterLayers[gl_GlobalInvocationID.z];
    if (row.info.w == 0u || any(greaterThanEqual(p, size))) return;
    const uint idLayer = row.info.w - 1u;
    const uint64_t v = depthIds[(idLayer * size.y + p.y) * size.x + p.x];
    const uint bits = uint(v >> 32);
    STORE_DEPTH(p, row.info.y, min(bits, kFar));
    imageStore(ids, ID_TEXEL(p, idLayer), uvec4(bits > kFar ? 0u : uint(v), 0u, 0u, 0u));
}
