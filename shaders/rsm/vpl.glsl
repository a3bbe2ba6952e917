// Virtual point lights read from the RSM arrays, and their irradiance at a receiver.
// Declared by the includer: rsmDepth, rsmNormal, rsmFlux (sampler2DArray), rsmLayers[].
#include "shared/octahedral.glsl"

// Irradiance at x (normal n) from the VPL in texel `t` of layer `layer`. A VPL is a small Lambertian
// reflector of flux phi: radiant intensity phi / pi * cos, so E = phi / pi * cos_p * cos_x / d^2.
// The seed's formula leaves out the 1/pi (its I_p = phi cos); keeping it makes RSM comparable with a
// path-traced bounce. d^2 is clamped to the VPL's own footprint so that near VPLs stay finite.
// A hair receiver (`hair`: n is its tangent) takes sin(t, w) in place of the receiver's cosine: the
// Kajiya-Kay diffuse term (dsm/kajiya_kay.glsl) of the light arriving from w.
struct Vpl {
    vec3 position, normal, flux;
    float footprint;  // the texel's area at the VPL (m^2): d^2 is clamped to it
};

// The VPL of texel `t` of layer `layer`; false where no surface is.
bool fetchVpl(ivec2 t, uint layer, out Vpl vpl) {
    float depth = texelFetch(rsmDepth, ivec3(t, layer), 0).r;
    if (depth >= 1.0) return false;  // no surface in this texel
    GpuRsmLayer L = rsmLayers[layer];
    vec2 uv = (vec2(t) + 0.5) / vec2(textureSize(rsmDepth, 0).xy);
    vpl.position = unproject(L.invViewProj, uv, depth);
    vpl.normal = octDecode(texelFetch(rsmNormal, ivec3(t, layer), 0).xy);
    vpl.flux = texelFetch(rsmFlux, ivec3(t, layer), 0).rgb;
    vpl.footprint = L.params.x * L.params.x;
    if (L.params.y > 0.5) {
        float z = abs((L.viewProj * vec4(vpl.position, 1.0)).w);  // clip w = depth along the axis
        vpl.footprint *= z * z;
    }
    return true;
}

vec3 vplIrradiance(Vpl vpl, vec3 x, vec3 n, bool hair) {
    vec3 v = x - vpl.position;
    float d2 = dot(v, v);
    float receiver = hair ? sqrt(max(d2 - dot(n, v) * dot(n, v), 0.0)) : max(dot(n, -v), 0.0);  // |v| cos or |v| sin
    d2 = max(d2, vpl.footprint);
    float geometry = max(dot(vpl.normal, v), 0.0) * receiver / (d2 * d2);
    return vpl.flux * (geometry / PI);
}

vec3 vplIrradiance(ivec2 t, uint layer, vec3 x, vec3 n, bool hair) {
    Vpl vpl;
    return fetchVpl(t, layer, vpl) ? vplIrradiance(vpl, x, n, hair) : vec3(0.0);
}
