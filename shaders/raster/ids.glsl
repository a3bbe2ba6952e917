// The body of raster/ids.comp and raster/ids_2d.comp (see there).
layout(local_size_x = 8, local_size_y = 8) in;
#include "raster/bindings.h"
layout(set = 0, binding = RASTER_IDS_DEPTH, std430) writeonly buffer Depth { uint depthBits[]; };
layout(set = 0, binding = RASTER_IDS_DEPTH_IDS, std430) readonly buffer DepthIds { uint64_t depthIds[]; };
layout(set = 0, binding = RASTER_IDS_LAYERS, std430) readonly buffer Layers { RasterLayer rasterLayers[]; };
#ifdef RASTER_ID_IMAGE_2D  // one layer (the camera's visibility buffer)
layout(set = 0, binding = RASTER_IDS_IMAGE, r32ui) uniform writeonly uimage2D ids;
#define ID_TEXEL(p, layer) ivec2(p)
#else
layout(set = 0, binding = RASTER_IDS_IMAGE, r32ui) uniform writeonly uimage2DArray ids;
#define ID_TEXEL(p, layer) ivec3(p, layer)
#endif
layout(push_constant) uniform Push { RasterPush push; };

const uint kFar = RASTER_FAR_BITS;  // ID layers are cleared above it (RASTER_ID_CLEAR_BITS)

void main() {
    const uvec2 size = uvec2(push.width, push.height);
    const uvec2 p = gl_GlobalInvocationID.xy;
    const RasterLayer row = rasterLayers[gl_GlobalInvocationID.z];
    if (row.idLayerPlusOne == 0u || any(greaterThanEqual(p, size))) return;
    const uint idLayer = row.idLayerPlusOne - 1u;
    const uint64_t v = depthIds[(idLayer * size.y + p.y) * size.x + p.x];
    const uint bits = uint(v >> 32);
    depthBits[(row.targetLayer * size.y + p.y) * size.x + p.x] = min(bits, kFar);
    imageStore(ids, ID_TEXEL(p, idLayer), uvec4(bits > kFar ? 0u : uint(v), 0u, 0u, 0u));
}
