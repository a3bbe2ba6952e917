#version 460
// Deferred direct lighting: one thread per pixel, every light, shadow visibility from the mask.
// Lambertian: L_o = albedo / pi * sum_lights E_light * max(0, n.l) * visibility.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "shared/types.h"
#include "lighting/lighting_bindings.h"
#include "core/lights.glsl"
#include "core/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = LIGHTING_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = LIGHTING_LIGHTS, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = LIGHTING_GBUFFER_ALBEDO) uniform sampler2D gAlbedo;
layout(set = 0, binding = LIGHTING_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = LIGHTING_GBUFFER_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = LIGHTING_SHADOW_MASK) uniform sampler2DArray shadowMask;  // shadow.filter: visibility per shadowed light
layout(set = 0, binding = LIGHTING_HDR, rgba32f) uniform writeonly image2D outImage;
layout(set = 0, binding = LIGHTING_INDIRECT) uniform sampler2D indirectIrradiance;  // GI (frame.giValid != 0)
layout(set = 0, binding = LIGHTING_SKY_IRRADIANCE) uniform sampler2D skyIrradiance;  // 1x1 black without a sky
layout(set = 0, binding = LIGHTING_PROBE, std430) writeonly buffer Probe { PixelProbe probe; };  // pixel FrameUniforms.probeX, probeY
// The sky's radiance, equirectangular in world directions (core/sky.h): black without a sky.
layout(set = 0, binding = LIGHTING_BACKGROUND_SKY) uniform sampler2D skyBackground;
// Velocity: which instance a pixel shows (visibility IDs, frame.visibilityIds) and where it was.
#define MOTION_FIRST_BINDING LIGHTING_MOTION_FIRST
#include "core/motion.glsl"
#include "sky/radiance.glsl"

#include "shadow/shadow_lookup.glsl"
#include "dsm/dsm_lookup.glsl"  // bindings 8-11: translucent casters (hair, blended meshes)
#include "dsm/kajiya_kay.glsl"

// What the lighting computes at one pixel; every AOV is read from it.
struct Shading {
    bool surface;
    vec3 albedo, n, p, direct, irradiance, indirect;
    float shadingModel, eyeDistance, firstShadow;
    bool hair;
};

Shading shade(ivec2 pixel) {
    Shading s;
    float depth = texelFetch(gDepth, pixel, 0).r;
    s.surface = depth < 1.0;
    s.eyeDistance = frame.farPlane;  // the background reads the far plane
    s.albedo = s.n = s.p = s.direct = s.irradiance = s.indirect = vec3(0.0);
    s.shadingModel = 0.0;
    s.firstShadow = 1.0;
    s.hair = false;
    if (!s.surface) return s;
    s.albedo = texelFetch(gAlbedo, pixel, 0).rgb;
    s.p = pixelWorldPosition(frame, pixel, depth);
    vec4 gn = texelFetch(gNormal, pixel, 0);
    s.n = normalize(gn.xyz);  // hair: its tangent
    s.shadingModel = gn.w;
    s.hair = gn.w > 1.5;      // SHADING_HAIR: Kajiya-Kay instead of Lambert
    vec3 toEye = frame.eye - s.p;
    s.eyeDistance = length(toEye);
    if (dot(s.n, toEye) < 0.0) s.n = -s.n;  // two-sided: shade the side the camera sees

    vec3 radiance = vec3(0.0), hairRadiance = vec3(0.0);
    bool seenShadow = false;
    for (uint i = 0; i < frame.lightCount; ++i) {
        GpuLight light = lights[i];
        vec3 l;
        vec3 e = incidentIrradiance(light, s.p, l);
        float ndotl = s.hair ? 1.0 : max(dot(s.n, l), 0.0);
        if (ndotl <= 0.0 || all(equal(e, vec3(0.0)))) {
            if (!seenShadow && light.shadowIndex != NO_SHADOW) { s.firstShadow = 0.0; seenShadow = true; }
            continue;
        }
        float v = shadowVisibility(light, pixel) * deepShadowTransmittance(i, s.p, s.n, s.hair);
        if (!seenShadow && light.shadowIndex != NO_SHADOW) { s.firstShadow = v; seenShadow = true; }
        if (s.hair) hairRadiance += e * v * kajiyaKay(s.albedo, s.n, l, normalize(toEye));
        else radiance += e * ndotl * v;
    }
    s.direct = radiance * s.albedo / PI + hairRadiance;
    // The sky's light is direct light: the visible sky's irradiance on a diffuse receiver.
    s.direct += s.albedo / PI * texelFetch(skyIrradiance, min(pixel, textureSize(skyIrradiance, 0) - 1), 0).rgb;
    // Indirect light of a diffuse receiver: albedo / pi times the gathered irradiance.
    if (frame.giValid != 0u) s.irradiance = texelFetch(indirectIrradiance, pixel, 0).rgb;
    s.indirect = s.albedo / PI * s.irradiance;
    return s;
}

// The velocity AOV: how far the surface at `pixel` (world position `p`) moved on the screen since
// the previous frame, in pixels (x right, y down): the pixel's centre minus where that point was then.
vec2 pixelVelocity(ivec2 pixel, vec3 p) {
    const vec4 clip = previousClip(pixel, texelFetch(gDepth, pixel, 0).r, p);
    return vec2(pixel) + 0.5 - (clip.xy / clip.w * 0.5 + 0.5) * vec2(frame.width, frame.height);
}

// The sky seen through `pixel`.
vec3 backgroundRadiance(ivec2 pixel) {
    return skyTextureRadiance(skyBackground, normalize(pixelWorldPosition(frame, pixel, 0.5) - frame.eye));
}

vec4 aovValue(Shading s, uint aov, ivec2 pixel) {
    if (aov == AOV_LPV_SLICE || aov == AOV_GV_SLICE)  // debug views drawn by lpv/gather.comp
        return vec4(texelFetch(indirectIrradiance, pixel, 0).rgb, 1.0);
    if (aov == AOV_DSM_LISTS)  // a light-space debug view: independent of the G-buffer
        return vec4(vec3(dsmListLengthAov(pixel, uvec2(frame.width, frame.height), frame.lightCount)), 1.0);
    // Alpha 0 marks the background (auto exposure leaves it out).
    if (!s.surface && (aov == AOV_FINAL || aov == AOV_DIRECT)) return vec4(backgroundRadiance(pixel), 0.0);
    if (!s.surface) return vec4(vec3(aov == AOV_DEPTH ? s.eyeDistance : 0.0), 0.0);
    if (aov == AOV_FINAL) return vec4(s.direct + s.indirect, 1.0);
    if (aov == AOV_DIRECT) return vec4(s.direct, 1.0);
    if (aov == AOV_INDIRECT) return vec4(s.indirect, 1.0);
    if (aov == AOV_ALBEDO) return vec4(s.albedo, 1.0);
    if (aov == AOV_NORMAL) return vec4(s.n, 1.0);
    if (aov == AOV_DEPTH) return vec4(vec3(s.eyeDistance), 1.0);
    if (aov == AOV_CASCADE) return vec4(shadowLayerColour(pixel), 1.0);
    if (aov == AOV_TRANSMITTANCE) return vec4(vec3(firstDeepShadowTransmittance(s.p, s.n, s.hair)), 1.0);
    if (aov == AOV_VELOCITY) return vec4(pixelVelocity(pixel, s.p), 0.0, 1.0);
    if (aov == AOV_SKY) return vec4(texelFetch(skyIrradiance, min(pixel, textureSize(skyIrradiance, 0) - 1), 0).rgb, 1.0);
    return vec4(vec3(s.firstShadow), 1.0);
}

void writeProbe(Shading s, ivec2 pixel) {
    probe.finalRadiance = s.direct + s.indirect;
    probe.surface = s.surface ? 1u : 0u;
    probe.direct = s.direct;
    probe.eyeDistance = s.eyeDistance;
    probe.indirect = s.indirect;
    probe.shadowVisibility = s.firstShadow;
    probe.irradiance = s.irradiance;
    probe.shadowLayer = s.surface ? firstShadowLayer(pixel) : -1.0;
    probe.albedo = s.albedo;
    probe.transmittance = s.surface ? firstDeepShadowTransmittance(s.p, s.n, s.hair) : 1.0;
    probe.normal = s.n;
    probe.shadingModel = s.shadingModel;
    probe.position = s.p;
    probe.pad0 = 0u;
    probe.velocity = s.surface ? pixelVelocity(pixel, s.p) : vec2(0.0);
    probe.pad1 = probe.pad2 = 0u;
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(frame.width, frame.height)))) return;
    Shading s = shade(pixel);
    imageStore(outImage, pixel, aovValue(s, frame.aov, pixel));
    if (all(equal(uvec2(pixel), uvec2(frame.probeX, frame.probeY)))) writeProbe(s, pixel);
}
