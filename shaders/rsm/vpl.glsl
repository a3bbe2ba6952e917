// Virtual point lights read from the RSM arrays, and their irradiance at a receiver.
// Declared by the includer: rsmDepth, rsmNormal, rsmFlux (sampler2DArray), rsmVpls (the three
// packed: usampler2DArray), rsmLayers[].
#include "shared/octahedral.glsl"

// The world position of the VPL of texel `t` of layer `layer`, whose RSM depth is `depth` (< 1).
vec3 vplPosition(ivec2 t, uint layer, float depth) {
    vec2 uv = (vec2(t) + 0.5) / vec2(textureSize(rsmDepth, 0).xy);
    return unproject(rsmLayers[layer].invViewProj, uv, depth);
}

// Irradiance at x (normal n) from the VPL in texel `t` of layer `layer`. A VPL is a small Lambertian
// reflector of flux phi: radiant intensity phi / pi * cos, so E = phi / pi * cos_p * cos_x / d^2.
// The seed's formula leaves out the 1/pi (its I_p = phi cos); keeping it makes RSM comparable with a
// path-traced bounce. d^2 is clamped to the VPL's own footprint so that near VPLs stay finite.
// A hair receiver (`hair`: n is its tangent) takes sin(t, w) in place of the receiver's cosine: the
// Kajiya-Kay diffuse term (dsm/kajiya_kay.glsl) of the light arriving from w.
// Written out in one function: a Vpl struct filled by a fetch function and read by a second kept
// the struct in memory and slowed the gather measurably.
// One fetch of the packed texel (rsm/resolve.comp, or a flux draw's copy of it): the gather is bound by
// the L2's random reads, so three fetches (depth, normal, flux) cost it more than the unpacking saves.
vec3 vplIrradianceOf(uvec4 vpl, ivec2 t, uint layer, vec3 x, vec3 n, bool hair) {
    float depth = uintBitsToFloat(vpl.x);
    if (depth >= 1.0) return vec3(0.0);  // no surface in this texel
    GpuRsmLayer L = rsmLayers[layer];
    vec3 xp = vplPosition(t, layer, depth);
    vec3 np = octDecode(unpackSnorm2x16(vpl.y));
    vec3 phi = vec3(unpackHalf2x16(vpl.z), unpackHalf2x16(vpl.w).x);
    vec3 v = x - xp;
    float d2 = dot(v, v);
    float footprint = L.texelSize * L.texelSize;
    if (L.perspective != 0u) {
        float z = abs((L.viewProj * vec4(xp, 1.0)).w);  // clip w = depth along the axis
        footprint *= z * z;
    }
    float receiver = hair ? sqrt(max(d2 - dot(n, v) * dot(n, v), 0.0)) : max(dot(n, -v), 0.0);  // |v| cos or |v| sin
    d2 = max(d2, footprint);
    float geometry = max(dot(np, v), 0.0) * receiver / (d2 * d2);
    return phi * (geometry / PI);
}

// The same, the VPL fetched from its texel.
vec3 vplIrradiance(ivec2 t, uint layer, vec3 x, vec3 n, bool hair) {
    return vplIrradianceOf(texelFetch(rsmVpls, ivec3(t, layer), 0), t, layer, x, n, hair);
}
