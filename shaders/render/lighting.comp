#version 460
// Deferred direct lighting: one thread per pixel, every light, shadow visibility from the mask.
// Lambertian: L_o = albedo / pi * sum_lights E_light * max(0, n.l) * visibility.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "render/lights.glsl"
#include "render/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = 1, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = 2) uniform sampler2D gAlbedo;
layout(set = 0, binding = 3) uniform sampler2D gNormal;
layout(set = 0, binding = 4) uniform sampler2D gDepth;
layout(set = 0, binding = 5) uniform sampler2DArray shadowMask;  // shadow.filter: visibility per shadowed light
layout(set = 0, binding = 6, rgba32f) uniform writeonly image2D outImage;
layout(set = 0, binding = 7) uniform sampler2D indirectIrradiance;  // GI (frame.options.x != 0)

#include "shadow/shadow_lookup.glsl"
#include "dsm/dsm_lookup.glsl"  // bindings 8-11: translucent casters (hair, blended meshes)
#include "dsm/kajiya_kay.glsl"

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(frame.size.xy)))) return;
    float depth = texelFetch(gDepth, pixel, 0).r;
    uint aov = frame.size.w;
    if (aov == AOV_LPV_SLICE || aov == AOV_GV_SLICE) {  // debug views drawn by lpv/gather.comp
        imageStore(outImage, pixel, vec4(texelFetch(indirectIrradiance, pixel, 0).rgb, 1.0));
        return;
    }
    if (aov == AOV_DSM_LISTS) {  // a light-space debug view: independent of the G-buffer
        imageStore(outImage, pixel, vec4(vec3(dsmListLengthAov(pixel, frame.size.xy, frame.size.z)), 1.0));
        return;
    }
    if (depth >= 1.0) {  // background: nothing, except the depth AOV which reads the far plane
        imageStore(outImage, pixel, vec4(vec3(aov == AOV_DEPTH ? frame.cameraPos.w : 0.0), 0.0));
        return;
    }
    vec3 albedo = texelFetch(gAlbedo, pixel, 0).rgb;
    vec3 p = pixelWorldPosition(frame, pixel, depth);
    vec4 gn = texelFetch(gNormal, pixel, 0);
    vec3 n = normalize(gn.xyz);  // hair: its tangent
    bool hair = gn.w > 1.5;      // SHADING_HAIR: Kajiya-Kay instead of Lambert
    vec3 toEye = frame.cameraPos.xyz - p;
    if (dot(n, toEye) < 0.0) n = -n;  // two-sided: shade the side the camera sees

    vec3 radiance = vec3(0.0), hairRadiance = vec3(0.0);
    float firstShadow = 1.0;
    bool seenShadow = false;
    for (uint i = 0; i < frame.size.z; ++i) {
        GpuLight light = lights[i];
        vec3 l;
        vec3 e = incidentIrradiance(light, p, l);
        float ndotl = hair ? 1.0 : max(dot(n, l), 0.0);
        if (ndotl <= 0.0 || all(equal(e, vec3(0.0)))) {
            if (!seenShadow && light.radiance.w != NO_SHADOW) { firstShadow = 0.0; seenShadow = true; }
            continue;
        }
        float v = shadowVisibility(light, pixel) * deepShadowTransmittance(i, p, n, hair);
        if (!seenShadow && light.radiance.w != NO_SHADOW) { firstShadow = v; seenShadow = true; }
        if (hair) hairRadiance += e * v * kajiyaKay(albedo, n, l, normalize(toEye));
        else radiance += e * ndotl * v;
    }
    radiance = radiance * albedo / PI + hairRadiance;
    // Indirect light of a diffuse receiver: albedo / pi times the gathered irradiance.
    vec3 indirect = frame.options.x != 0u ? albedo / PI * texelFetch(indirectIrradiance, pixel, 0).rgb : vec3(0.0);

    vec4 outValue;
    if (aov == AOV_FINAL) outValue = vec4(radiance + indirect, 1.0);
    else if (aov == AOV_DIRECT) outValue = vec4(radiance, 1.0);
    else if (aov == AOV_INDIRECT) outValue = vec4(indirect, 1.0);
    else if (aov == AOV_ALBEDO) outValue = vec4(albedo, 1.0);
    else if (aov == AOV_NORMAL) outValue = vec4(n, 1.0);
    else if (aov == AOV_DEPTH) outValue = vec4(vec3(length(toEye)), 1.0);
    else if (aov == AOV_CASCADE) outValue = vec4(shadowLayerColour(pixel), 1.0);
    else if (aov == AOV_TRANSMITTANCE) outValue = vec4(vec3(firstDeepShadowTransmittance(p, n, hair)), 1.0);
    else outValue = vec4(vec3(firstShadow), 1.0);
    imageStore(outImage, pixel, outValue);
}
