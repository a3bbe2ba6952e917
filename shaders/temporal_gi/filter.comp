#version 460
// One iteration of the edge-aware a-trous filter of the accumulated indirect irradiance (after Schied
// et al. 2017, "Spatiotemporal Variance-Guided Filtering"): a 3x3 kernel (1/4, 1/2, 1/4 per axis)
// whose taps lie `step` pixels apart, each weighted down where it leaves the pixel's surface (its
// distance off the tangent plane, in pixel footprints at that spacing; its normal) and where its
// luminance differs by more than the pixel's noise explains. The noise is the standard deviation of
// the accumulated mean, sqrt(variance / frames), from the history's moments; for a history of fewer
// than kFramesForVariance frames it is estimated over the pixel's 3x3 neighbourhood instead. Hair pixels (their
// G-buffer holds a strand's tangent, and neighbouring strands are no surface) are left as they are.
// The guide is the history's geometry of this frame (view depth, normal), 8 bytes a tap; a tap's
// offset from the pixel's tangent plane comes from its view depth along a ray that is affine in the
// pixel coordinates, so no tap is unprojected.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "shared/luminance.glsl"
#include "shared/octahedral.glsl"
#include "temporal_gi/bindings.h"
#include "core/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = GI_FILTER_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = GI_FILTER_GUIDE) uniform sampler2D guide;
layout(set = 0, binding = GI_FILTER_INPUT) uniform sampler2D filterInput;
layout(set = 0, binding = GI_FILTER_MOMENTS) uniform sampler2D moments;
layout(set = 0, binding = GI_FILTER_OUTPUT, rgba16f) uniform writeonly image2D outFiltered;
layout(push_constant) uniform Push { GiFilterPush pc; };

const float kFramesForVariance = 4.0;
const float kNormalPower = 64.0;


// rgb and the standard deviation of the luminance (< 0: unknown) at pixel q.
vec4 inputAt(ivec2 q) {
    const vec4 c = texelFetch(filterInput, q, 0);
    if (pc.firstIteration == 0u) return c;
    const vec2 m = texelFetch(moments, q, 0).xy;
    const float sigma = c.a >= kFramesForVariance ? sqrt(max(m.y - m.x * m.x, 0.0) / c.a) : -1.0;
    return vec4(c.rgb, sigma);
}

// A short history's noise, estimated in space instead (as SVGF does): the standard deviation of the
// luminance over the 3x3 pixels of the same surface (guide flag) around p. A smooth estimate (LPV's)
// keeps its detail from the first frame; a noisy one (few RSM samples) is smoothed.
float spatialSigma(ivec2 p, ivec2 size) {
    vec2 m = vec2(0.0);
    float n = 0.0;
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            const ivec2 q = clamp(p + ivec2(i, j), ivec2(0), size - 1);
            if (texelFetch(guide, q, 0).w < 0.5) continue;
            const float l = luminance(texelFetch(filterInput, q, 0).rgb);
            m += vec2(l, l * l);
            n += 1.0;
        }
    m /= max(n, 1.0);
    return sqrt(max(m.y - m.x * m.x, 0.0));
}

// The ray from the eye through pixel coordinate p (continuous, pixel centres at + 0.5), scaled to a
// view depth of 1: world position = eye + viewDepth * ray(p).
vec3 unitDepthRay(vec2 p) {
    const vec2 uv = p / vec2(frame.width, frame.height);
    const vec3 x = unproject(frame.invViewProj, uv, 0.5);
    return (x - frame.eye) / (frame.viewProj * vec4(x, 1.0)).w;
}

void main() {
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    const ivec2 size = ivec2(frame.width, frame.height);
    if (any(greaterThanEqual(pixel, size))) return;
    vec4 centre = inputAt(pixel);
    const vec4 g = texelFetch(guide, pixel, 0);
    if (g.w < 0.5) {
        imageStore(outFiltered, pixel, centre);
        return;
    }
    if (pc.firstIteration != 0u && centre.a < 0.0) centre.a = spatialSigma(pixel, size);
    const vec3 n = octDecode(g.yz);
    // n . ray(p) is affine in p: its value at the pixel and its steps along x and y.
    const vec3 ray = unitDepthRay(vec2(pixel) + 0.5);
    const float nRay = dot(n, ray), nRayX = dot(n, unitDepthRay(vec2(pixel) + vec2(1.5, 0.5)) - ray),
                nRayY = dot(n, unitDepthRay(vec2(pixel) + vec2(0.5, 1.5)) - ray);
    const float planeAtPixel = g.x * nRay;  // n . (x_p - eye)
    const float footprint = g.x * frame.pixelSpread * float(pc.step);
    const float lumCentre = luminance(centre.rgb);
    const float lumScale = centre.a >= 0.0 ? 1.0 / (pc.luminanceSigma * centre.a + 1e-4 * lumCentre + 1e-9) : 0.0;
    const float kernel[2] = float[2](0.5, 0.25);
    vec3 sum = vec3(0.0);
    float weights = 0.0, variance = 0.0;
    for (int j = -1; j <= 1; ++j) {
        for (int i = -1; i <= 1; ++i) {
            const ivec2 offset = ivec2(i, j) * int(pc.step), q = pixel + offset;
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            const vec4 gq = texelFetch(guide, q, 0);
            if (gq.w < 0.5) continue;
            const vec4 c = inputAt(q);
            const float offPlane = abs(gq.x * (nRay + float(offset.x) * nRayX + float(offset.y) * nRayY) - planeAtPixel);
            const float w = kernel[abs(i)] * kernel[abs(j)] * pow(max(dot(n, octDecode(gq.yz)), 0.0), kNormalPower) *
                            exp(-offPlane / footprint - abs(luminance(c.rgb) - lumCentre) * lumScale);
            sum += w * c.rgb;
            weights += w;
            const float tapSigma = c.a >= 0.0 ? c.a : max(centre.a, 0.0);  // a fresh tap: the centre's estimate
            variance += w * w * tapSigma * tapSigma;
        }
    }
    // The centre tap always counts (weight 0.25), so weights > 0.
    const float sigma = centre.a >= 0.0 ? sqrt(variance) / weights : -1.0;
    imageStore(outFiltered, pixel, vec4(sum / weights, sigma));
}
