// Camera translucency build (src/dsm/translucency.h): every hair or BLEND fragment (raster, or hair
// in compute: dsm/ribbon_raster.glsl) in front of the opaque surface (the G-buffer depth), in two steps
// (OitBuildPush.buckets.store), as the DSM's (dsm/dsm_insert.glsl): first counted in its pixel's depth
// bucket, its -log(1 - alpha) added to the pixel's sum; then, after oit.offsets gave the kept buckets
// places in the pixel's run, stored there as a node (one atomic add, two stores); a fragment of a
// bucket left out stores nothing. Needs `draw` (OitBuildPush) and, in the
// includer, GL_EXT_shader_atomic_int64 with 64-bit integer types.
#include "dsm/bindings.h"
layout(set = 0, binding = OIT_BUILD_NODES, std430) writeonly buffer Nodes { uvec4 nodes[]; };
layout(set = 0, binding = OIT_BUILD_NORMALS, std430) writeonly buffer Normals { uint normals[]; };
layout(set = 0, binding = OIT_BUILD_STATS, std430) buffer Stats { OitStats stats; };
layout(set = 0, binding = OIT_BUILD_OPAQUE_DEPTH) uniform sampler2D opaqueDepth;
layout(set = 0, binding = OIT_BUILD_BUCKETS, std430) buffer Buckets { uint buckets[]; };   // per pixel, OitPush.bucketsPerPixel
layout(set = 0, binding = OIT_BUILD_TAILS, std430) buffer Tails { uint64_t tails[]; };  // per pixel, OIT_LOG_SCALE

#include "dsm/octahedral.glsl"
#include "dsm/depth_buckets.glsl"

// `segment`: a hair fragment's segment (the index of its first point), OIT_NOT_HAIR for a mesh's.
void oitInsert(ivec2 pixel, float depth, vec3 albedo, float alpha, vec3 normal, uint segment) {
    // Nothing to composite; NaN too: lavapipe's raster can give a fragment of a strip's degenerate
    // join (dsm/hair.vert) non-finite interpolants (one pixel of the hair at 1280x720).
    if (!(alpha > 0.0)) return;
    // Behind (or on) the opaque surface: hidden (a coplanar translucent surface loses to the opaque one).
    float opaque = texelFetch(opaqueDepth, pixel, 0).r;
    if (depth >= opaque) return;
    // The alpha the node will hold (a half), clamped so that alpha 1 stays finite: the composite takes
    // the kept layers' share out of the pixel's sum (oit_blend.comp). A fragment whose half is 0 adds
    // nothing to the image and is left out; every counted one adds at least 1 to the sum (oit.offsets
    // reads the counts only where the sum is not 0).
    alpha = min(alpha, 1.0);
    float stored = unpackHalf2x16(packHalf2x16(vec2(alpha, 0.0))).x;
    if (stored <= 0.0) return;
    uint p = uint(pixel.y) * draw.width + uint(pixel.x);
    uint slot = p * draw.buckets.perCell + depthBucketBefore(depth, draw.buckets, opaque);
    if (draw.buckets.store == 0u) {  // the first step: count
        atomicAdd(buckets[slot], 1u);
        float optical = max(-log(max(1.0 - stored, 1e-7)), 0.0);  // >= 0 whatever the log's rounding
        atomicAdd(tails[p], max(uint64_t(optical * OIT_LOG_SCALE + 0.5), 1ul));
        return;
    }
    uint node = atomicAdd(buckets[slot], 1u);
    if (node >= DSM_CULLED) return;  // behind the cap's bucket (its sum is all that counts), or no room
    nodes[node] = uvec4(floatBitsToUint(depth), packHalf2x16(albedo.rg), segment,
                        packHalf2x16(vec2(albedo.b, alpha)));
    normals[node] = packSnorm2x16(octEncode(normal));
}
