#version 460
// LPV final gather: the accumulated intensity I (SH per cell) read trilinearly at the receiver moved
// one cell along its normal (against leaking through thin walls, and away from the cell its own VPLs
// were injected into, half a cell out, whose outgoing L1 lobe cancels the light coming in: with half
// a cell the GI suite's room is 28% too dark; the price, a brighter near field: docs/techniques/lpv.md), irradiance
// E = max(0, dot(I, CosineLobe(-n))) / cell^2 (intensity per cell cross-section is radiance; the
// clamped-cosine integral against it is irradiance), summed over the cascades (lpvIrradiance).
// Debug modes show a volume slice.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "lpv/bindings.h"
#include "core/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = LPV_GATHER_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = LPV_GATHER_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = LPV_GATHER_GBUFFER_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = LPV_GATHER_SUM, std430) readonly buffer Accumulated { vec4 accum[]; };
layout(set = 0, binding = LPV_GATHER_GEOMETRY, std430) readonly buffer GeometryVolume { vec4 geometry[]; };
layout(set = 0, binding = LPV_GATHER_IRRADIANCE, rgba32f) uniform writeonly image2D outIrradiance;
layout(push_constant) uniform Push { LpvPush pc; };

#include "lpv/sh.glsl"
#include "lpv/volume.glsl"

// `half_` 0: the near half of the running sum (every step of cascade 0), 1: the far half (lpv.h).
vec3 irradianceIn(uint k, uint half_, vec3 x, vec3 n, bool hair) {
    uint offset = half_ * 3u * pc.cascadeCount * cellsPerVolume();
    vec3 g = gridCoord(k, x) - 0.5;
    ivec3 base = ivec3(floor(g));
    vec3 f = g - vec3(base);
    vec4 lobe = hair ? hairLobe() : cosineLobe(-n);
    vec3 e = vec3(0.0);
    for (int i = 0; i < 8; ++i) {
        ivec3 o = ivec3(i & 1, (i >> 1) & 1, i >> 2);
        ivec3 c = clamp(base + o, ivec3(0), ivec3(pc.resolution) - 1);
        vec3 w3 = mix(1.0 - f, f, vec3(o));
        float w = w3.x * w3.y * w3.z;
        for (uint ch = 0; ch < 3u; ++ch) e[ch] += w * dot(accum[offset + lightIndex(k, ch, c)], lobe);
    }
    float cell = pc.cascades[k].cellSize;
    return max(e, vec3(0.0)) / (cell * cell);
}

// 1 deep inside cascade k, falling to 0 over the last `band` cells before its border.
float insideWeight(uint k, vec3 x) {
    vec3 g = gridCoord(k, x);
    float inside = min(min(g.x, min(g.y, g.z)), float(pc.resolution) - max(g.x, max(g.y, g.z)));
    return clamp((inside - 1.0) / pc.blendCells, 0.0, 1.0);
}

// Cascades add up: each coarser one carries only the light that has gone beyond the reach of the
// finer one's steps (its far half), plus its near half where the finer one does not hold the
// receiver (outside it, blended over the border band). The outermost holds whatever is left.
// A hair receiver (`hair`, n its tangent) has no side to step towards: it reads the cells at x.
vec3 lpvIrradiance(vec3 x, vec3 n, bool hair) {
    vec3 e = vec3(0.0);
    float finer = 0.0;  // how much the next finer cascade holds x
    for (uint k = 0; k < pc.cascadeCount; ++k) {
        float inside = k + 1u == pc.cascadeCount ? 1.0 : insideWeight(k, x);
        vec3 p = hair ? x : x + pc.cascades[k].cellSize * n;
        if (k > 0u && inside > 0.0) e += inside * irradianceIn(k, 1u, p, n, hair);
        if (finer < 1.0 && inside > 0.0) e += inside * (1.0 - finer) * irradianceIn(k, 0u, p, n, hair);
        finer = inside;
    }
    return e;
}

// Debug slice of cascade 0: the image spans the slice; light shows mean intensity, geometry the
// peak blocking.
vec3 slice(ivec2 pixel) {
    uint axis = pc.sliceAxis;
    vec2 uv = (vec2(pixel) + 0.5) / vec2(frame.width, frame.height);
    ivec2 p = ivec2(uv * float(pc.resolution));
    ivec3 c = axis == 0u ? ivec3(pc.sliceIndex, p.x, p.y) : axis == 1u ? ivec3(p.x, pc.sliceIndex, p.y)
                                                                    : ivec3(p.x, p.y, pc.sliceIndex);
    if (frame.aov == AOV_GV_SLICE) return vec3(geometry[geometryIndex(0u, c)].x * SH_C0 * LOBE_PEAK / (LOBE_C0 * SH_C0));
    return vec3(accum[lightIndex(0u, 0u, c)].x, accum[lightIndex(0u, 1u, c)].x, accum[lightIndex(0u, 2u, c)].x) * SH_C0;
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(frame.width, frame.height)))) return;
    vec3 e = vec3(0.0);
    if (frame.aov == AOV_LPV_SLICE || frame.aov == AOV_GV_SLICE) {
        e = slice(pixel);
    } else {
        float depth = texelFetch(gDepth, pixel, 0).r;
        if (depth < 1.0) {
            vec3 x = pixelWorldPosition(frame, pixel, depth);
            vec4 g = texelFetch(gNormal, pixel, 0);
            vec3 n = normalize(g.xyz);
            bool hair = g.w > 1.5;  // SHADING_HAIR (--translucency off): n is the strand's tangent
            if (!hair && dot(n, frame.eye - x) < 0.0) n = -n;
            e = lpvIrradiance(x, n, hair);
        }
    }
    imageStore(outIrradiance, pixel, vec4(e, 1.0));
}
