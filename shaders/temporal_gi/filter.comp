#version 460
// One iteration of the edge-aware a-trous filter of the accumulated indirect irradiance (Schied et
// al. 2017, "Spatiotemporal Variance-Guided Filtering"): a 5x5 B3-spline kernel whose taps lie
// `step` pixels apart, each weighted down where it leaves the pixel's surface (its distance off the
// tangent plane, in pixel footprints at that spacing; its normal) and where its luminance differs
// by more than the pixel's noise explains. The noise is the standard deviation of the accumulated
// mean, sqrt(variance / frames), from the history's moments; for a history of fewer than
// kFramesForVariance frames it is unknown and only the geometry stops the filter, so a fresh pixel
// is smoothed over its surface while a converged one keeps its detail. Hair pixels (their G-buffer
// holds a strand's tangent, and neighbouring strands are no surface) are left as they are.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "temporal_gi/bindings.h"
#include "render/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = GI_FILTER_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = GI_FILTER_GBUFFER_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = GI_FILTER_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = GI_FILTER_INPUT) uniform sampler2D filterInput;
layout(set = 0, binding = GI_FILTER_MOMENTS) uniform sampler2D moments;
layout(set = 0, binding = GI_FILTER_OUTPUT, rgba16f) uniform writeonly image2D outFiltered;
layout(push_constant) uniform Push { GiFilterPush pc; };

const float kFramesForVariance = 4.0;
const float kNormalPower = 64.0;

float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

// rgb and the standard deviation of the luminance (< 0: unknown) at pixel q.
vec4 inputAt(ivec2 q) {
    const vec4 c = texelFetch(filterInput, q, 0);
    if (pc.firstIteration == 0u) return c;
    const vec2 m = texelFetch(moments, q, 0).xy;
    const float sigma = c.a >= kFramesForVariance ? sqrt(max(m.y - m.x * m.x, 0.0) / c.a) : -1.0;
    return vec4(c.rgb, sigma);
}

bool isSurface(vec4 normal) { return normal.w < 1.5; }  // not SHADING_HAIR

void main() {
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    const ivec2 size = ivec2(frame.width, frame.height);
    if (any(greaterThanEqual(pixel, size))) return;
    const vec4 centre = inputAt(pixel);
    const float depth = texelFetch(gDepth, pixel, 0).r;
    const vec4 normal = texelFetch(gNormal, pixel, 0);
    if (depth >= 1.0 || !isSurface(normal)) {
        imageStore(outFiltered, pixel, centre);
        return;
    }
    const vec3 n = normalize(normal.xyz), x = pixelWorldPosition(frame, pixel, depth);
    const float footprint = (frame.viewProj * vec4(x, 1.0)).w * frame.pixelSpread * float(pc.step);
    const float lumCentre = luminance(centre.rgb);
    const float lumScale = centre.a >= 0.0 ? 1.0 / (pc.luminanceSigma * centre.a + 1e-4 * lumCentre + 1e-9) : 0.0;
    const float kernel[3] = float[3](0.375, 0.25, 0.0625);
    vec3 sum = vec3(0.0);
    float weights = 0.0, variance = 0.0;
    for (int j = -2; j <= 2; ++j) {
        for (int i = -2; i <= 2; ++i) {
            const ivec2 q = pixel + ivec2(i, j) * int(pc.step);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            const float qDepth = texelFetch(gDepth, q, 0).r;
            const vec4 qNormal = texelFetch(gNormal, q, 0);
            if (qDepth >= 1.0 || !isSurface(qNormal)) continue;
            const vec4 c = inputAt(q);
            const float offPlane = abs(dot(n, pixelWorldPosition(frame, q, qDepth) - x)) / footprint;
            const float w = kernel[abs(i)] * kernel[abs(j)] *
                            pow(max(dot(n, normalize(qNormal.xyz)), 0.0), kNormalPower) *
                            exp(-offPlane - abs(luminance(c.rgb) - lumCentre) * lumScale);
            sum += w * c.rgb;
            weights += w;
            variance += w * w * max(c.a, 0.0) * max(c.a, 0.0);
        }
    }
    // The centre tap always counts (weight 0.140625), so weights > 0.
    const float sigma = centre.a >= 0.0 ? sqrt(variance) / weights : -1.0;
    imageStore(outFiltered, pixel, vec4(sum / weights, sigma));
}
