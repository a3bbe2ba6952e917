#version 460
// RSM indirect gather: for a receiver, sum the irradiance of VPLs around its projection into each
// RSM layer, at the polar sample offsets of Dachsbacher & Stamminger (r_max * xi1 * (sin, cos)(2 pi
// xi2), generated once from a seed on the CPU with their density-compensating weights), or over
// every texel (exact mode, for tests). Writes irradiance; lighting multiplies by albedo / pi.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "render/lights.glsl"
#include "render/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = 1) uniform sampler2D gNormal;
layout(set = 0, binding = 2) uniform sampler2D gDepth;
layout(set = 0, binding = 3) uniform sampler2DArray rsmDepth;
layout(set = 0, binding = 4) uniform sampler2DArray rsmNormal;
layout(set = 0, binding = 5) uniform sampler2DArray rsmFlux;
layout(set = 0, binding = 6, std430) readonly buffer Layers { GpuRsmLayer rsmLayers[]; };
layout(set = 0, binding = 7, std430) readonly buffer Samples { vec4 samples[]; };  // xy offset (uv), z weight
layout(set = 0, binding = 8, rgba32f) uniform writeonly image2D outIrradiance;
layout(set = 0, binding = 9, std430) readonly buffer PixelList { uvec4 header; uvec2 pixels[]; } list;
layout(push_constant) uniform Push { RsmPush pc; };

#include "rsm/vpl.glsl"

// Centre and radius of the sampling disc for receiver x. The pattern is centred on x's projection.
// A receiver outside the map (for a spot light: outside its pyramid, or behind it, like a ceiling
// above a downward spot) has no texel of its own: its disc starts at the map border in x's direction
// and, as x leaves the map (angle off the axis for a spot, uv distance for an orthographic map),
// slides to the map centre while growing to the whole map. The result stays continuous across the
// frustum's border, and the weights scale with the disc's area, so the estimate keeps converging to
// the sum over its disc.
float samplingDisc(GpuRsmLayer layer, vec3 x, out vec2 st) {
    vec4 clip = layer.viewProj * vec4(x, 1.0);
    const float rMax = pc.params.z, whole = max(rMax, 0.70710678);
    float outside;
    vec2 border;
    if (layer.params.y > 0.5) {
        float m = max(abs(clip.x), abs(clip.y));
        float angle = atan(m, clip.w);  // 0 on the axis, pi/4 at the map's border, pi straight behind
        if (angle <= 0.78539816) {
            st = clip.xy / clip.w * 0.5 + 0.5;
            return rMax;
        }
        border = 0.5 + 0.5 * clip.xy / m;
        outside = (angle - 0.78539816) / 2.35619449;
    } else {
        vec2 p = clip.xy / clip.w * 0.5 + 0.5;
        border = clamp(p, vec2(0.0), vec2(1.0));
        if (border == p) {
            st = p;
            return rMax;
        }
        outside = min(2.0 * length(p - border), 1.0);
    }
    st = mix(border, vec2(0.5), outside);
    return mix(rMax, whole, outside);
}

// Per-receiver rotation of the sample pattern, seeded by the receiver's world position (quantised to
// RSM texels): neighbouring receivers see different VPLs, so the interpolation's filter averages
// independent estimates, and the pattern of a surface point stays put when the camera moves.
uint hash3(uvec3 v) {
    uint h = v.x * 0x8da6b343u ^ v.y * 0xd8163841u ^ v.z * 0xcb1ab31fu;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    return h ^ (h >> 16);
}

mat2 patternRotation(GpuRsmLayer L, vec3 x) {
    float texel = L.params.x;
    if (L.params.y > 0.5) texel *= max(abs((L.viewProj * vec4(x, 1.0)).w), 1e-3);
    float angle = float(hash3(uvec3(ivec3(floor(x / texel))))) * (6.28318531 / 4294967296.0);
    float c = cos(angle), s = sin(angle);
    return mat2(c, s, -s, c);
}

// Visibility of a far VPL (texel t) from x, the cheap way: two points on the segment between them (0.3
// and 0.6 of the way from the VPL; one nearer x finds x's own shadow, not an occluder),
// each compared with the RSM's depth where it projects; a point behind the surface the light sees
// there lies in that surface's shadow, so something stands between the VPL and x. Far VPLs are
// where light would otherwise leak through walls (closed galleries, building interiors).
float farVisibility(GpuRsmLayer L, uint layer, ivec2 t, vec3 x) {
    float depth = texelFetch(rsmDepth, ivec3(t, layer), 0).r;
    if (depth >= 1.0) return 1.0;
    int res = int(pc.sizes.z);
    vec3 xp = unproject(L.invViewProj, (vec2(t) + 0.5) / float(res), depth);
    for (int k = 1; k <= 2; ++k) {
        vec4 c = L.viewProj * vec4(mix(xp, x, 0.3 * float(k)), 1.0);
        if (c.w <= 0.0) continue;
        vec3 ndc = c.xyz / c.w;
        vec2 uv = ndc.xy * 0.5 + 0.5;
        if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) continue;
        float seen = texelFetch(rsmDepth, ivec3(ivec2(uv * float(res)), layer), 0).r;
        if (ndc.z > seen + 0.01 * (1.0 - seen) + 1e-4) return 0.0;
    }
    return 1.0;
}

// The four VPLs around RSM position uv, weighted bilinearly: the same expected light as the texel uv
// falls in, but continuous in uv, so that it does not jump when the texel lattice moves under a sample.
vec3 bilinearVplIrradiance(vec2 uv, int res, uint layer, vec3 x, vec3 n, bool hair) {
    const vec2 f = uv * float(res) - 0.5;
    const ivec2 t0 = ivec2(floor(f));
    const vec2 w = f - vec2(t0);
    vec3 e = vec3(0.0);
    for (int k = 0; k < 4; ++k) {
        const ivec2 o = ivec2(k & 1, k >> 1);
        const float weight = (o.x == 1 ? w.x : 1.0 - w.x) * (o.y == 1 ? w.y : 1.0 - w.y);
        e += weight * vplIrradiance(clamp(t0 + o, ivec2(0), ivec2(res - 1)), layer, x, n, hair);
    }
    return e;
}

vec3 gather(vec3 x, vec3 n, bool hair) {
    vec3 e = vec3(0.0);
    const int res = int(pc.sizes.z);
    uint usedCascadeLight = 0xFFFFFFFFu;
    for (uint layer = 0; layer < pc.mode.z; ++layer) {
        // Cascades of a light: the first whose map holds x, else the last (seed: SearchCascadeIndex).
        GpuRsmLayer L = rsmLayers[layer];
        if (L.cascade.x > 0.0) {
            if (uint(L.params.z) == usedCascadeLight) continue;
            vec4 c = L.viewProj * vec4(x, 1.0);
            if (L.cascade.y < 0.5 && any(greaterThan(abs(c.xy / c.w), vec2(1.0)))) continue;
            usedCascadeLight = uint(L.params.z);
        }
        if (pc.mode.x == RSM_GATHER_ALL_TEXELS) {
            for (int ty = 0; ty < res; ++ty)
                for (int tx = 0; tx < res; ++tx) e += vplIrradiance(ivec2(tx, ty), layer, x, n, hair);
            continue;
        }
        vec2 st;
        float scale = samplingDisc(L, x, st) * L.cascade.z / pc.params.z;
        mat2 rotation = patternRotation(L, x);
        for (uint i = 0; i < pc.mode.y; ++i) {
            vec4 s = samples[i];
            vec2 uv = st + rotation * s.xy * scale;
            if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) continue;
            ivec2 t = ivec2(uv * float(res));
            vec3 c = pc.sizes.w != 0u ? bilinearVplIrradiance(uv, res, layer, x, n, hair) : vplIrradiance(t, layer, x, n, hair);
            if (s.w > 0.5 && any(greaterThan(c, vec3(0.0)))) c *= farVisibility(L, layer, t, x);
            e += (s.z * scale * scale) * c;
        }
    }
    return e;
}

void main() {
    ivec2 out_ = ivec2(gl_GlobalInvocationID.xy);
    ivec2 pixel = out_;
    if (pc.mode.x == RSM_GATHER_LIST) {
        uint index = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * 8u;
        if (index >= list.header.x) return;
        pixel = out_ = ivec2(list.pixels[index]);
    } else {
        if (any(greaterThanEqual(out_, ivec2(pc.sizes.xy)))) return;
        if (pc.mode.x == RSM_GATHER_LOWRES)  // the cell's representative (centre) full-res pixel
            pixel = min(out_ * int(pc.mode.w) + int(pc.mode.w) / 2, ivec2(frame.size.xy) - 1);
    }
    float depth = texelFetch(gDepth, pixel, 0).r;
    vec3 e = vec3(0.0);
    if (depth < 1.0) {
        vec3 x = pixelWorldPosition(frame, pixel, depth);
        vec4 g = texelFetch(gNormal, pixel, 0);
        vec3 n = normalize(g.xyz);
        bool hair = g.w > 1.5;  // SHADING_HAIR (--translucency off): n is the strand's tangent
        if (!hair && dot(n, frame.cameraPos.xyz - x) < 0.0) n = -n;
        e = gather(x, n, hair);
    }
    imageStore(outIrradiance, out_, vec4(e, 1.0));
}
