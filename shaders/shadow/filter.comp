#version 460
// shadow.filter: the visibility of every shadowed light at every pixel, with the light's filter
// (hard, PCF, PCSS, VSM, EVSM, MSM), into the shadow mask that the lighting pass reads. A pass of
// its own so that each filter's cost shows in the per-pass GPU timings.
// Mask layer s (= GpuLight.shadowIndex): r = visibility, g = layer code for the `cascade` AOV
// (cascade index + blend fraction towards the next one, cube face, hemisphere).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "shared/types.h"
#include "core/lights.glsl"
#include "core/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

#include "shadow/bindings.h"
layout(set = 0, binding = SHADOW_MASK_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = SHADOW_MASK_LIGHTS, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = SHADOW_MASK_GBUFFER_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = SHADOW_MASK_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = SHADOW_MASK_DEPTH_MAP) uniform sampler2DArray shadowDepth;
layout(set = 0, binding = SHADOW_MASK_MOMENTS) uniform sampler2DArray shadowMoments;
layout(set = 0, binding = SHADOW_MASK_LAYERS, std430) readonly buffer Layers { GpuShadowLayer shadowLayers[]; };
layout(set = 0, binding = SHADOW_MASK_SHADOW_LIGHTS, std430) readonly buffer ShadowLights { GpuShadowLight shadowLights[]; };
layout(set = 0, binding = SHADOW_MASK_PARAMS) uniform Params { GpuShadowParams params; };
layout(set = 0, binding = SHADOW_MASK_OUT, rg16f) uniform writeonly image2DArray shadowMask;

#include "shadow/project.glsl"
#include "shadow/moments.glsl"
#include "shadow/pcf.glsl"
#include "shadow/visibility.glsl"

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(frame.width, frame.height)))) return;
    float depth = texelFetch(gDepth, pixel, 0).r;
    if (depth >= 1.0) return;  // background: the lighting pass reads no shadow there
    vec3 p = pixelWorldPosition(frame, pixel, depth);
    vec4 gn = texelFetch(gNormal, pixel, 0);
    vec3 n = normalize(gn.xyz);
    bool hair = gn.w > 1.5;  // SHADING_HAIR: n is the strand's tangent (src/dsm), lit from every side
    if (dot(n, frame.eye - p) < 0.0) n = -n;  // two-sided, as the lighting pass shades
    float angle = kernelAngle(pixel);
    for (uint i = 0u; i < frame.lightCount; ++i) {
        GpuLight light = lights[i];
        if (light.shadowIndex == NO_SHADOW) continue;
        uint index = uint(light.shadowIndex);
        vec3 l;
        vec3 e = incidentIrradiance(light, p, l);
        // Where the light does not reach, the lighting pass reads no visibility: skip the filter.
        bool visible = (hair || dot(n, l) > 0.0) && any(greaterThan(e, vec3(0.0)));
        // A strand has no normal to offset along: it is offset towards the light.
        vec2 result = lightVisibility(shadowLights[index], light, p, hair ? l : n, angle, visible);
        imageStore(shadowMask, ivec3(pixel, int(index)), vec4(result, 0.0, 0.0));
    }
}
