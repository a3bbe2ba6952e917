#version 460
// The visible sky's irradiance (names::kSkyIrradiance): the sky share that trace.comp found, averaged
// over the pixels of the same surface around (a SKY_TILE^2 block holds every ray rotation), times
// the irradiance the unoccluded sky gives the pixel's own normal. Background pixels get the open
// sky's irradiance of an upward surface, for translucent layers drawn over them.
#extension GL_GOOGLE_include_directive : require
#include "sky_light/types.h"
#include "core/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = SKY_FILTER_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = SKY_FILTER_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = SKY_FILTER_GBUFFER_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = SKY_FILTER_VISIBILITY) uniform sampler2D visibility;
layout(set = 0, binding = SKY_FILTER_OUT, rgba16f) uniform writeonly image2D outIrradiance;
layout(push_constant) uniform Push { SkyLightPush pc; };
#include "sky_light/sky_sh.glsl"
#include "sky_light/surface.glsl"

// How much a neighbour's share counts: only on the receiver's own surface (its plane, within a few
// per cent of the distance, and a normal within about 25 degrees).
float neighbourWeight(SkyReceiver r, SkyReceiver q) {
    if (!q.surface) return 0.0;
    const float plane = abs(dot(q.p - r.p, r.n)) / max(length(frame.eye - r.p), 1e-4);
    return (plane < 0.02 && dot(q.n, r.n) > 0.9) ? 1.0 : 0.0;
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
    const int radius = int(pc.filterRadius);
    vec3 share = vec3(0.0);
    float weight = 0.0;
    for (int y = -radius; y <= radius; ++y)
        for (int x = -radius; x <= radius; ++x) {
            const ivec2 q = pixel + ivec2(x, y);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            const float w = (x == 0 && y == 0) ? 1.0 : neighbourWeight(r, skyReceiver(q));
            share += w * texelFetch(visibility, q, 0).rgb;
            weight += w;
        }
    imageStore(outIrradiance, pixel, vec4(skyIrradiance(pc, r.n) * share / weight, 1.0));
}
