#version 460
// The visible sky's irradiance (names::kSkyIrradiance) at every camera pixel: the filtered sky share
// of the four traced receivers around it, each by its bilinear weight and by how well it lies on the
// pixel's surface, times the irradiance the unoccluded sky gives the pixel's own normal. A pixel that
// none of them shares a surface with (a strand, an edge thinner than the trace step) takes their
// bilinear mix. Background pixels get the open sky's irradiance of an upward surface, for
// translucent layers drawn over them.
#extension GL_GOOGLE_include_directive : require
#include "sky_light/types.h"
#include "core/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = SKY_UPSAMPLE_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = SKY_UPSAMPLE_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = SKY_UPSAMPLE_GBUFFER_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = SKY_UPSAMPLE_SHARE) uniform sampler2D share;
layout(set = 0, binding = SKY_UPSAMPLE_OUT, rgba32f) uniform writeonly image2D outIrradiance;
layout(push_constant) uniform Push { SkyLightPush pc; };
#define SKY_SH_BINDING SKY_UPSAMPLE_SKY_SH
#include "sky_light/sky_sh.glsl"
#include "sky_light/surface.glsl"
#include "sky_light/rays.glsl"

void main() {
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    const ivec2 size = ivec2(frame.width, frame.height);
    if (any(greaterThanEqual(pixel, size))) return;
    const SkyReceiver r = skyReceiver(pixel);
    if (!r.surface) {
        imageStore(outIrradiance, pixel, vec4(skyIrradiance(vec3(0.0, 1.0, 0.0)), 0.0));
        return;
    }
    // Texel t stands at pixel t * step + step / 2: the pixel's place between the texels around it.
    const float step = float(pc.traceStep);
    const vec2 at = (vec2(pixel) - float(pc.traceStep / 2u)) / step;
    const ivec2 base = ivec2(floor(at));
    const vec2 f = at - vec2(base);
    const ivec2 texels = textureSize(share, 0);
    vec3 onSurface = vec3(0.0), mixed = vec3(0.0);
    float weight = 0.0, mixedWeight = 0.0;
    for (int k = 0; k < 4; ++k) {
        const ivec2 o = ivec2(k & 1, k >> 1);
        const ivec2 q = clamp(base + o, ivec2(0), texels - 1);
        const float bilinear = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
        if (bilinear <= 0.0) continue;
        const ivec2 qPixel = min(tracedPixel(q, pc.traceStep), size - 1);
        const float w = bilinear * (qPixel == pixel ? 1.0 : surfaceWeight(r, skyReceiver(qPixel)));
        const vec3 s = texelFetch(share, q, 0).rgb;
        onSurface += w * s;
        weight += w;
        mixed += bilinear * s;
        mixedWeight += bilinear;
    }
    const vec3 visible = weight > 1e-3 * mixedWeight ? onSurface / weight : mixed / max(mixedWeight, 1e-6);
    imageStore(outIrradiance, pixel, vec4(skyIrradiance(r.n) * visible, 1.0));
}
