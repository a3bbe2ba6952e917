#version 460
// The visible sky's irradiance (names::kSkyIrradiance) at every camera pixel: the sky share that
// weigh.comp found at the traced receivers around it (a SKY_TILE^2 block of them holds every ray
// rotation), averaged over those on the pixel's own surface, times the irradiance the unoccluded
// sky gives the pixel's own normal. Background pixels get the open sky's irradiance of an upward
// surface, for translucent layers drawn over them.
#extension GL_GOOGLE_include_directive : require
#include "sky_light/types.h"
#include "core/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = SKY_FILTER_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = SKY_FILTER_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = SKY_FILTER_GBUFFER_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = SKY_FILTER_SHARE) uniform sampler2D share;
layout(set = 0, binding = SKY_FILTER_OUT, rgba16f) uniform writeonly image2D outIrradiance;
layout(push_constant) uniform Push { SkyLightPush pc; };
#include "sky_light/sky_sh.glsl"
#include "sky_light/surface.glsl"
#include "sky_light/rays.glsl"

// How much a traced receiver's share counts at a pixel: by how near it lies to the pixel's tangent
// plane (per cent of the distance) and how alike their normals are. Smooth, not a cut: bumpy shading
// normals and curved cloth would leave a cut with too few receivers and show the rotations' pattern.
float surfaceWeight(SkyReceiver r, SkyReceiver q) {
    if (!q.surface) return 0.0;
    const float plane = abs(dot(q.p - r.p, r.n)) / max(length(frame.eye - r.p), 1e-4) / 0.02;
    const float facing = max(dot(q.n, r.n), 0.0);
    const float facing2 = facing * facing, facing4 = facing2 * facing2;
    return exp(-plane * plane) * facing4 * facing4;
}

void main() {
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    const ivec2 size = ivec2(frame.width, frame.height);
    if (any(greaterThanEqual(pixel, size))) return;
    const SkyReceiver r = skyReceiver(pixel);
    if (!r.surface) {
        imageStore(outIrradiance, pixel, vec4(skyIrradiance(pc, vec3(0.0, 1.0, 0.0)), 0.0));
        return;
    }
    // The traced texels around the pixel; a pixel no traced receiver of its surface is near (a
    // strand, an edge thinner than the trace step) takes the plain average of them all.
    const int step = int(pc.traceStep), radius = int(pc.filterRadius);
    const ivec2 texels = textureSize(share, 0);
    const ivec2 centre = pixel / step;
    vec3 onSurface = vec3(0.0), around = vec3(0.0);
    float weight = 0.0, count = 0.0;
    for (int y = -radius; y <= radius; ++y)
        for (int x = -radius; x <= radius; ++x) {
            const ivec2 q = centre + ivec2(x, y);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, texels))) continue;
            const ivec2 qPixel = tracedPixel(q, pc.traceStep);
            const vec3 s = texelFetch(share, q, 0).rgb;
            // The outermost row and column count half: a window of 4k + 1 receivers then holds each of
            // a SKY_TILE^2 block's ray rotations equally often, wherever it stands.
            const float edge = radius == 0 ? 1.0 : (abs(x) == radius ? 0.5 : 1.0) * (abs(y) == radius ? 0.5 : 1.0);
            const bool inside = all(lessThan(qPixel, size));
            const float w = edge * (qPixel == pixel ? 1.0 : (inside ? surfaceWeight(r, skyReceiver(qPixel)) : 0.0));
            onSurface += w * s;
            weight += w;
            around += edge * s;
            count += edge;
        }
    const vec3 visible = weight > 1e-3 ? onSurface / weight : around / max(count, 1e-6);
    imageStore(outIrradiance, pixel, vec4(skyIrradiance(pc, r.n) * visible, 1.0));
}
