#version 460
// Temporal accumulation of the indirect irradiance (--gi-temporal): per pixel, the previous frame's
// accumulated irradiance where this pixel's surface point was (reprojected with the previous camera
// and the instance's motion: render/motion.glsl), blended with this frame's: h + alpha (e - h). The
// history is rejected (this frame's alone) where the point was off the image or hidden: the view depth
// stored with the history differs from the point's by more than 2%.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "render/gi_history_bindings.h"
#include "render/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = GI_HISTORY_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = GI_HISTORY_CURRENT) uniform sampler2D current;        // gi.irradiance of this frame
layout(set = 0, binding = GI_HISTORY_GBUFFER_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = GI_HISTORY_HISTORY) uniform sampler2D history;
layout(set = 0, binding = GI_HISTORY_HISTORY_DEPTH) uniform sampler2D historyDepth;   // view depth of each history pixel
layout(set = 0, binding = GI_HISTORY_OUT, rgba16f) uniform writeonly image2D outHistory;
layout(set = 0, binding = GI_HISTORY_OUT_DEPTH, r32f) uniform writeonly image2D outDepth;
layout(push_constant) uniform Push { GiHistoryPush pc; };
#define MOTION_FIRST_BINDING GI_HISTORY_MOTION_FIRST
#include "render/motion.glsl"

// Bilinear in float weights (a sampler's filter may round them to a few bits: a point reprojected onto
// a texel's centre within float error must read that texel).
vec4 historyAt(vec2 uv) {
    const ivec2 last = ivec2(frame.width, frame.height) - 1;
    const vec2 f = uv * vec2(frame.width, frame.height) - 0.5;
    const ivec2 t = ivec2(floor(f));
    const vec2 w = f - vec2(t);
    const vec4 a = texelFetch(history, clamp(t, ivec2(0), last), 0);
    const vec4 b = texelFetch(history, clamp(t + ivec2(1, 0), ivec2(0), last), 0);
    const vec4 c = texelFetch(history, clamp(t + ivec2(0, 1), ivec2(0), last), 0);
    const vec4 d = texelFetch(history, clamp(t + ivec2(1, 1), ivec2(0), last), 0);
    return mix(mix(a, b, w.x), mix(c, d, w.x), w.y);
}

void main() {
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(frame.width, frame.height)))) return;
    const vec4 e = texelFetch(current, pixel, 0);
    const float depth = texelFetch(gDepth, pixel, 0).r;
    if (depth >= 1.0) {
        imageStore(outHistory, pixel, e);
        imageStore(outDepth, pixel, vec4(0.0));
        return;
    }
    const vec3 p = pixelWorldPosition(frame, pixel, depth);
    const float viewDepth = (frame.viewProj * vec4(p, 1.0)).w;
    vec4 result = e;
    const vec4 clip = previousClip(pixel, depth, p);
    if (pc.historyValid != 0u && clip.w > 0.0) {
        const vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
        const ivec2 then = ivec2(floor(uv * vec2(frame.width, frame.height)));
        if (all(greaterThanEqual(then, ivec2(0))) && all(lessThan(then, ivec2(frame.width, frame.height)))) {
            const float stored = texelFetch(historyDepth, then, 0).r;
            if (abs(stored - clip.w) <= 0.02 * clip.w) {
                const vec4 h = historyAt(uv);
                result = h + pc.alpha * (e - h);
            }
        }
    }
    imageStore(outHistory, pixel, result);
    imageStore(outDepth, pixel, vec4(viewDepth));
}
