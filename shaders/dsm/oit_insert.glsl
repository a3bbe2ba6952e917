// Camera translucency build (src/dsm/translucency.h): every hair or BLEND fragment (raster, or hair
// in compute: dsm/ribbon_raster.glsl) in front of the opaque surface (the G-buffer depth) pushes a
// node onto one of its pixel's OIT_CHAINS lists, as the DSM build does (dsm/dsm_insert.glsl). Needs `draw` (HairDrawPush: ids.z = image width, ids.w = node capacity).
layout(set = 0, binding = 5, std430) buffer Heads { uint heads[]; };
layout(set = 0, binding = 6, std430) writeonly buffer Nodes { uvec4 nodes[]; };
layout(set = 0, binding = 7, std430) writeonly buffer Normals { uint normals[]; };
layout(set = 0, binding = 8, std430) buffer Stats { OitStats stats; };
layout(set = 0, binding = 9) uniform sampler2D opaqueDepth;

#include "dsm/octahedral.glsl"

void oitInsert(ivec2 pixel, float depth, vec3 albedo, float alpha, vec3 normal, bool hair) {
    // Nothing to composite; NaN too: lavapipe's raster can give a fragment of a strip's degenerate
    // join (dsm/hair.vert) non-finite interpolants (one pixel of the hair at 1280x720).
    if (!(alpha > 0.0)) return;
    // Behind (or on) the opaque surface: hidden (a coplanar translucent surface loses to the opaque one).
    if (depth >= texelFetch(opaqueDepth, pixel, 0).r) return;
    uint node = atomicAdd(stats.counts.x, 1u);
    if (node >= draw.ids.w) return;  // pool full: counted, dropped
    uint chain = node % OIT_CHAINS;  // the pixel's lists, walked side by side by the composite
    uint previous = atomicExchange(heads[(uint(pixel.y) * draw.ids.z + uint(pixel.x)) * OIT_CHAINS + chain], node);
    alpha = min(alpha, 1.0);
    nodes[node] = uvec4(floatBitsToUint(depth), packHalf2x16(albedo.rg), previous,
                        packHalf2x16(vec2(albedo.b, hair ? -alpha : alpha)));
    normals[node] = packSnorm2x16(octEncode(normal));
}
