#version 460
// The sky share that weigh.comp found at each traced receiver, averaged over the traced receivers of
// its own surface around it: a SKY_TILE^2 block of them holds every ray rotation. Runs at the traced
// receivers' size; upsample.comp takes it to every pixel.
#extension GL_GOOGLE_include_directive : require
#include "sky_light/types.h"
#include "core/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = SKY_FILTER_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = SKY_FILTER_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = SKY_FILTER_GBUFFER_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = SKY_FILTER_SHARE) uniform sampler2D share;
layout(set = 0, binding = SKY_FILTER_OUT, rgba16f) uniform writeonly image2D outShare;
layout(push_constant) uniform Push { SkyLightPush pc; };
#include "sky_light/surface.glsl"
#include "sky_light/rays.glsl"

void main() {
    const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    const ivec2 texels = textureSize(share, 0);
    if (any(greaterThanEqual(texel, texels))) return;
    const ivec2 size = ivec2(frame.width, frame.height);
    const SkyReceiver r = skyReceiver(min(tracedPixel(texel, pc.traceStep), size - 1));
    if (!r.surface) {
        imageStore(outShare, texel, vec4(1.0));
        return;
    }
    const int radius = int(pc.filterRadius);
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    for (int y = -radius; y <= radius; ++y)
        for (int x = -radius; x <= radius; ++x) {
            const ivec2 q = texel + ivec2(x, y);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, texels))) continue;
            // The outermost row and column count half: a window of 4k + 1 receivers then holds each of
            // a SKY_TILE^2 block's ray rotations equally often, wherever it stands.
            const float edge = radius == 0 ? 1.0 : (abs(x) == radius ? 0.5 : 1.0) * (abs(y) == radius ? 0.5 : 1.0);
            const ivec2 qPixel = tracedPixel(q, pc.traceStep);
            const float surface = (x == 0 && y == 0) ? 1.0
                                  : (all(lessThan(qPixel, size)) ? surfaceWeight(r, skyReceiver(qPixel)) : 0.0);
            sum += edge * surface * texelFetch(share, q, 0).rgb;
            weight += edge * surface;
        }
    imageStore(outShare, texel, vec4(sum / weight, 1.0));
}
