// The DSM build's one job per light-space fragment (raster or compute, dsm/ribbon_raster.glsl): allocate a node from
// the pool (one atomic add), count it in its texel's depth bucket (one atomic add: the node's place among the
// bucket's, which dsm.scatter turns into a place in the texel's run) and store it (one store). No lists: the
// resolve reads a texel's nodes from that run, not by walking pointers (dsm/resolve.comp). Needs `draw` (HairDrawPush:
// ids.x = DSM layer, ids.z = the scene light, or DSM_NONE for no depth test, ids.w = capacity).
// A full pool drops the fragment; the counter keeps counting, so the overflow is known exactly and
// no list ever points at a node that was not written.
//
// Depth test against the opaque casters: a fragment hidden behind the light's ordinary shadow map
// everywhere a receiver could look it up from (its DSM texel and the lookup's filter around it,
// two DSM texels in all, however the two maps' resolutions and projections differ) casts onto
// nothing that the opaque casters leave lit: it takes no node. Conservative: it is dropped only
// when every shadow-map texel of that neighbourhood holds a nearer opaque depth than the fragment
// moved two DSM texels towards the light.
layout(set = 0, binding = 5, std430) buffer Buckets { uint buckets[]; };  // per texel, DsmPush.buckets.x counts
layout(set = 0, binding = 6, std430) writeonly buffer Nodes { uvec4 nodes[]; };
layout(set = 0, binding = 7, std430) buffer Stats { DsmStats stats; };
layout(set = 0, binding = 8, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = 9, std430) readonly buffer ShadowLights { GpuShadowLight shadowLights[]; };
layout(set = 0, binding = 10, std430) readonly buffer ShadowLayers { GpuShadowLayer shadowLayers[]; };
layout(set = 0, binding = 11) uniform sampler2DArray opaqueShadowMap;  // "shadow.map", nearest

// Whether shadow layer `index` holds an opaque depth nearer than q over the whole neighbourhood of
// `reach` world units around q (false where the layer does not cover it).
bool hiddenInLayer(uint index, vec3 q, float reach) {
    GpuShadowLayer layer = shadowLayers[index];
    if (layer.info.x == SHADOW_PROJ_PARABOLOID) return false;
    vec4 clip = layer.viewProj * vec4(q, 1.0);
    if (clip.w <= 0.0) return false;
    vec3 ndc = clip.xyz / clip.w;
    ivec2 size = textureSize(opaqueShadowMap, 0).xy;
    float texel = layer.params.x * (layer.info.x == SHADOW_PROJ_ORTHO ? 1.0 : clip.w);
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
    if (draw.ids.z == DSM_NONE) return false;
    GpuLight light = lights[draw.ids.z];
    if (light.radiance.w == NO_SHADOW) return false;
    GpuShadowLight s = shadowLights[uint(light.radiance.w)];
    if (s.info.z != SHADOW_KIND_SINGLE && s.info.z != SHADOW_KIND_CASCADES) return false;
    float dsmTexel = draw.footprint.x * (draw.footprint.y > 0.5 ? distance(world, draw.viewer.xyz) : 1.0);
    vec3 towardsLight = draw.viewer.w > 0.5 ? normalize(draw.viewer.xyz - world) : draw.viewer.xyz;
    vec3 q = world + towardsLight * (2.0 * dsmTexel);
    for (uint k = 0; k < s.info.y; ++k)
        if (hiddenInLayer(s.info.x + k, q, 2.0 * dsmTexel)) return true;
    return false;
}

void dsmInsert(uvec2 texel, float depth, float alpha, vec3 world) {
    if (!(alpha > 0.0)) return;  // nothing to cast (NaN too: see oit_insert.glsl)
    if (hiddenByOpaque(world)) {
        atomicAdd(stats.build.y, 1u);
        return;
    }
    uint node = atomicAdd(stats.build.x, 1u);
    if (node >= draw.ids.w) return;
    uint res = uint(draw.footprint.z);
    uint index = (draw.ids.x * res + texel.y) * res + texel.x;
    uint bucket = uint(clamp((depth - draw.buckets.x) * draw.buckets.y, 0.0, draw.buckets.z - 1.0));
    uint place = atomicAdd(buckets[index * uint(draw.buckets.z) + bucket], 1u);  // shared/types.h
    nodes[node] = uvec4(floatBitsToUint(depth), floatBitsToUint(min(alpha, 1.0)), index, place | bucket << DSM_BUCKET_SHIFT);
}
