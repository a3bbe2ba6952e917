// The DSM build's one job per light-space fragment (raster or compute, dsm/ribbon_raster.glsl), in two steps
// (DsmBuildPush.buckets.store): first count it in its texel's depth bucket (one atomic add), then, after dsm.offsets
// gave each bucket a place in its texel's run, store its (depth, alpha) there (one atomic add, one store), unless its
// bucket lies behind the list cap's (or found no room): it takes no memory at all. Both steps make the same
// fragments: the same code, the same pipeline. No lists: the resolve reads a texel's fragments from its run.
// Needs `draw` (DsmBuildPush).
//
// Depth test against the opaque casters: a fragment hidden behind the light's ordinary shadow map
// everywhere a receiver could look it up from (its DSM texel and the lookup's filter around it,
// two DSM texels in all, however the two maps' resolutions and projections differ) casts onto
// nothing that the opaque casters leave lit: it takes no node. Conservative: it is dropped only
// when every shadow-map texel of that neighbourhood holds a nearer opaque depth than the fragment
// moved two DSM texels towards the light.
// Per texel DsmPush.bucketsPerTexel bucket counts, then their places in the texel's run (dsm.offsets).
#include "dsm/bindings.h"
layout(set = 0, binding = DSM_BUILD_BUCKETS, std430) buffer Buckets { uint buckets[]; };
layout(set = 0, binding = DSM_BUILD_RUNS, std430) writeonly buffer Runs { uvec2 runs[]; };  // (depth, alpha) bits
layout(set = 0, binding = DSM_BUILD_STATS, std430) buffer Stats { DsmStats stats; };
layout(set = 0, binding = DSM_BUILD_LIGHTS, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = DSM_BUILD_SHADOW_LIGHTS, std430) readonly buffer ShadowLights { GpuShadowLight shadowLights[]; };
layout(set = 0, binding = DSM_BUILD_SHADOW_LAYERS, std430) readonly buffer ShadowLayers { GpuShadowLayer shadowLayers[]; };
layout(set = 0, binding = DSM_BUILD_SHADOW_MAP) uniform sampler2DArray opaqueShadowMap;  // "shadow.map", nearest

#include "dsm/depth_buckets.glsl"

// Whether shadow layer `index` holds an opaque depth nearer than q over the whole neighbourhood of
// `reach` world units around q (false where the layer does not cover it).
bool hiddenInLayer(uint index, vec3 q, float reach) {
    GpuShadowLayer layer = shadowLayers[index];
    if (layer.projection == SHADOW_PROJ_PARABOLOID) return false;
    vec4 clip = layer.viewProj * vec4(q, 1.0);
    if (clip.w <= 0.0) return false;
    vec3 ndc = clip.xyz / clip.w;
    ivec2 size = textureSize(opaqueShadowMap, 0).xy;
    float texel = layer.texelSize * (layer.projection == SHADOW_PROJ_ORTHO ? 1.0 : clip.w);
    int r = int(ceil(reach / texel));
    if (r > 4) return false;  // a shadow map much finer than the DSM: not worth the taps (kept)
    ivec2 c = ivec2(floor((ndc.xy * 0.5 + 0.5) * vec2(size)));
    if (any(lessThan(c - r, ivec2(0))) || any(greaterThanEqual(c + r + 1, size))) return false;
    // The fragment's own texel first (most visible fragments leave here), then the neighbourhood in
    // 2x2 gathers (a (2r+2)^2 block: one row and column more than needed, still conservative).
    if (texelFetch(opaqueShadowMap, ivec3(c, int(index)), 0).r >= ndc.z) return false;
    vec2 inv = 1.0 / vec2(size);
    for (int y = -r; y <= r; y += 2)
        for (int x = -r; x <= r; x += 2) {
            vec4 d = textureGather(opaqueShadowMap, vec3((vec2(c + ivec2(x, y)) + 1.0) * inv, float(index)), 0);
            if (any(greaterThanEqual(d, vec4(ndc.z)))) return false;  // a lit receiver may see it
        }
    return true;
}

bool hiddenByOpaque(vec3 world) {
    if (draw.depthTestLight == DSM_NONE) return false;
    GpuLight light = lights[draw.depthTestLight];
    if (light.shadowIndex == NO_SHADOW) return false;
    GpuShadowLight s = shadowLights[uint(light.shadowIndex)];
    if (s.kind != SHADOW_KIND_SINGLE && s.kind != SHADOW_KIND_CASCADES) return false;
    float dsmTexel = draw.view.pixelSize * (draw.view.perspective != 0u ? distance(world, draw.view.viewer) : 1.0);
    vec3 towardsLight = draw.view.viewerIsPoint != 0u ? normalize(draw.view.viewer - world) : draw.view.viewer;
    vec3 q = world + towardsLight * (2.0 * dsmTexel);
    for (uint k = 0; k < s.layerCount; ++k)
        if (hiddenInLayer(s.firstLayer + k, q, 2.0 * dsmTexel)) return true;
    return false;
}

void dsmInsert(uvec2 texel, float depth, float alpha, vec3 world) {
    if (!(alpha > 0.0)) return;  // nothing to cast (NaN too: see oit_insert.glsl)
    bool counting = draw.buckets.store == 0u;
    if (hiddenByOpaque(world)) {
        if (counting) atomicAdd(stats.hidden, 1u);
        return;
    }
    uint res = draw.resolution;
    uint index = (draw.viewRow * res + texel.y) * res + texel.x;
    uint at = atomicAdd(buckets[index * draw.buckets.perCell + depthBucket(depth, draw.buckets)], 1u);
    if (!counting && at < DSM_CULLED) runs[at] = uvec2(floatBitsToUint(depth), floatBitsToUint(min(alpha, 1.0)));
}
