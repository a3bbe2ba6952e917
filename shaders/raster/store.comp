#version 460
// The compute rasterizer's last pass for targets that compute can write (src/raster): the depth
// buffer's layers stored into the R32_SFLOAT shadow map that the filters sample. It replaces a
// buffer-to-image copy into a D32_SFLOAT map, which NVIDIA's driver runs at about a fifth of the
// copy bandwidth (0.72 ms for Sponza's four 2048^2 cascades on the H100). One thread per texel,
// z = row of the layer table; layers with IDs are stored by raster/ids_image.comp instead.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, std430) readonly buffer Depth { uint depthBits[]; };
layout(set = 0, binding = 1, std430) readonly buffer Layers { RasterLayer rasterLayers[]; };
layout(set = 0, binding = 2, r32f) uniform writeonly image2DArray depthMap;
layout(push_constant) uniform Push { RasterPush push; };

void main() {
    const uvec2 size = uvec2(push.target.x, push.capacity.w);
    const uvec2 p = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(p, size))) return;
    const RasterLayer row = rasterLayers[gl_GlobalInvocationID.z];
    if (row.info.w != 0u) return;
    const uint layer = row.info.y;
    const float depth = uintBitsToFloat(depthBits[(layer * size.y + p.y) * size.x + p.x]);
    imageStore(depthMap, ivec3(p, layer), vec4(depth, 0.0, 0.0, 0.0));
}
