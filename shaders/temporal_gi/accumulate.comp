#version 460
// Temporal accumulation of the indirect irradiance. Per pixel: where its surface point was in the
// previous frame (core/motion.glsl: the previous camera and the instance's motion), the history
// there, bilinear over the taps that hold the same surface (view depth within 2%, normals within
// about 25 degrees: the rest are disoccluded), blended with this frame's estimate at weight
// alpha = max(1 / frames, minWeight, changeWeight, detected). frames counts the frames the history
// spans, so a new history is a plain mean of its first frames; changeWeight is the host's measure of
// how much the lights changed (src/temporal_gi/temporal_gi_technique.cpp); detected, the GI
// technique's own measure per pixel, where it publishes one (temporal gradients). The history also carries the
// luminance's first two moments, from which the spatial filter knows each pixel's noise.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "shared/luminance.glsl"
#include "shared/octahedral.glsl"
#include "temporal_gi/bindings.h"
#include "core/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = GI_ACCUMULATE_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = GI_ACCUMULATE_CURRENT) uniform sampler2D current;
layout(set = 0, binding = GI_ACCUMULATE_GBUFFER_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = GI_ACCUMULATE_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = GI_ACCUMULATE_HISTORY_COLOR) uniform sampler2D historyColor;
layout(set = 0, binding = GI_ACCUMULATE_HISTORY_MOMENTS) uniform sampler2D historyMoments;
layout(set = 0, binding = GI_ACCUMULATE_HISTORY_GEOMETRY) uniform sampler2D historyGeometry;
layout(set = 0, binding = GI_ACCUMULATE_OUT_COLOR, rgba32f) uniform writeonly image2D outColor;
layout(set = 0, binding = GI_ACCUMULATE_OUT_MOMENTS, rg32f) uniform writeonly image2D outMoments;
layout(set = 0, binding = GI_ACCUMULATE_OUT_GEOMETRY, rgba16f) uniform writeonly image2D outGeometry;
layout(set = 0, binding = GI_ACCUMULATE_CHANGE) uniform sampler2D changeWeight;  // temporal_gi/change_weight.comp
layout(push_constant) uniform Push { GiAccumulatePush pc; };
#define MOTION_FIRST_BINDING GI_ACCUMULATE_MOTION_FIRST
#include "core/motion.glsl"

const float kDepthTolerance = 0.02;  // relative view depth
const float kNormalCos = 0.9;
// The moments' weight never falls below this: the variance the filter reads follows the last few
// frames, not the whole history (Schied et al. 2017).
const float kMomentsMinWeight = 0.2;


struct History {
    vec4 color;    // rgb irradiance, a frames
    vec2 moments;
    bool found;
};

// The history where this pixel's surface point (normal n) was: `clip`, its previous clip position
// (w: its previous view depth). Bilinear in float weights over the taps that hold that surface.
History reprojectedHistory(vec4 clip, vec3 n) {
    History h = History(vec4(0.0), vec2(0.0), false);
    if (pc.historyValid == 0u || clip.w <= 0.0) return h;
    const ivec2 size = ivec2(frame.width, frame.height);
    const vec2 f = (clip.xy / clip.w * 0.5 + 0.5) * vec2(size) - 0.5;
    const ivec2 t0 = ivec2(floor(f));
    const vec2 w = f - vec2(t0);
    float total = 0.0;
    for (int k = 0; k < 4; ++k) {
        const ivec2 t = t0 + ivec2(k & 1, k >> 1);
        if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, size))) continue;
        const vec4 g = texelFetch(historyGeometry, t, 0);
        if (g.x <= 0.0 || abs(g.x - clip.w) > kDepthTolerance * clip.w) continue;
        if (dot(octDecode(g.yz), n) < kNormalCos) continue;
        const float weight = ((k & 1) != 0 ? w.x : 1.0 - w.x) * ((k >> 1) != 0 ? w.y : 1.0 - w.y);
        h.color += weight * texelFetch(historyColor, t, 0);
        h.moments += weight * texelFetch(historyMoments, t, 0).xy;
        total += weight;
    }
    if (total < 1e-3) return h;
    h.color /= total;
    h.moments /= total;
    h.found = h.color.a > 0.0;
    return h;
}

void main() {
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(frame.width, frame.height)))) return;
    const vec3 e = texelFetch(current, pixel, 0).rgb;
    const float l = luminance(e);
    const float depth = texelFetch(gDepth, pixel, 0).r;
    if (depth >= 1.0) {  // background: nothing to accumulate
        imageStore(outColor, pixel, vec4(e, 0.0));
        imageStore(outMoments, pixel, vec4(l, l * l, 0.0, 0.0));
        imageStore(outGeometry, pixel, vec4(0.0));
        return;
    }
    const vec3 p = pixelWorldPosition(frame, pixel, depth);
    const float viewDepth = (frame.viewProj * vec4(p, 1.0)).w;
    const vec4 gn = texelFetch(gNormal, pixel, 0);
    const vec3 n = normalize(gn.xyz);
    const History h = reprojectedHistory(previousClip(pixel, depth, p), n);
    const float frames = h.found ? h.color.a + 1.0 : 1.0;
    const float detected = pc.changePixels == 0u ? 0.0 : texelFetch(changeWeight, pixel / int(pc.changePixels), 0).r;
    const float alpha = max(max(1.0 / frames, pc.minWeight), max(pc.changeWeight, detected));
    const vec3 color = h.found ? mix(h.color.rgb, e, alpha) : e;
    const vec2 moments = h.found ? mix(h.moments, vec2(l, l * l), max(alpha, kMomentsMinWeight)) : vec2(l, l * l);
    // The frames the blend is worth: a raised weight shortens the history to 1 / alpha.
    imageStore(outColor, pixel, vec4(color, 1.0 / alpha));
    imageStore(outMoments, pixel, vec4(moments, 0.0, 0.0));
    // w: 1 where the spatial filter may take and give light (a surface; not a hair strand, whose
    // G-buffer holds its tangent).
    imageStore(outGeometry, pixel, vec4(viewDepth, octEncode(n), gn.w < 1.5 ? 1.0 : 0.0));
}
