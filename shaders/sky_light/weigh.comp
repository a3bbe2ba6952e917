#version 460
// The share of the sky's radiance, per colour channel, that a traced receiver's clear rays see
// (trace.comp's mask weighed by the sky of this frame): the filter multiplies it by the unoccluded
// irradiance, so a receiver that sees only the horizon takes the horizon's colour and an open one
// is exact.
#extension GL_GOOGLE_include_directive : require
#include "sky_light/types.h"
#include "core/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = SKY_WEIGH_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = SKY_WEIGH_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = SKY_WEIGH_GBUFFER_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = SKY_WEIGH_CLEAR_RAYS, rg32ui) uniform readonly uimage2D clearRays;
layout(set = 0, binding = SKY_WEIGH_OUT, rgba16f) uniform writeonly image2D outShare;
layout(push_constant) uniform Push { SkyLightPush pc; };
#include "sky/radiance.glsl"
layout(set = 0, binding = SKY_WEIGH_SKY_RADIANCE) uniform sampler2D skyRadianceMap;
#include "sky_light/surface.glsl"
#include "sky_light/rays.glsl"

void main() {
    const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, imageSize(outShare)))) return;
    const ivec2 pixel = min(tracedPixel(texel, pc.traceStep), ivec2(frame.width, frame.height) - 1);
    const SkyReceiver r = skyReceiver(pixel);
    const uint mask = imageLoad(clearRays, texel).r;
    if (!r.surface || pc.rays == 0u || mask == 0xFFFFFFFFu) {
        imageStore(outShare, texel, vec4(1.0));
        return;
    }
    const float rank = tileRank(texel);
    vec3 seen = vec3(0.0), total = vec3(0.0);
    uint clear = 0u;
    for (uint k = 0u; k < pc.rays; ++k) {
        const vec3 d = rayDirection(r.n, k, pc.rays, rank);
        // Weighted by the sky's own radiance (its SH would move weight from the horizon to the
        // zenith), above the horizon only: below it the ground blocks the rays.
        const vec3 l = d.y > 0.0 ? skyTextureRadiance(skyRadianceMap, d) : vec3(0.0);
        total += l;
        if ((mask & (1u << k)) != 0u) {
            seen += l;
            ++clear;
        }
    }
    // A ray set that sees no radiance at all (a black sky's side) counts its clear rays instead.
    const vec3 share = mix(seen / max(total, vec3(1e-20)), vec3(float(clear) / float(pc.rays)),
                           vec3(lessThanEqual(total, vec3(0.0))));
    imageStore(outShare, texel, vec4(share, 1.0));
}
