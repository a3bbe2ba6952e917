#version 460
// Camera translucency, second pass (src/dsm/translucency.h): one thread per kept layer of any pixel
// (oit_sort.comp's list, an indirect dispatch), so that every thread does one layer's lighting: the
// per-pixel pass lit a pixel's up to OIT_MAX_LIST layers one after another, its lanes idle wherever
// a neighbour had more. The layer is lit like an opaque surface (every light with its shadow-map
// filter and its deep shadow map, or for hair under a DSM its strand's shadow from
// oit_hair_shadow.comp; Lambert or Kajiya-Kay; plus the indirect irradiance gathered at the pixel's
// opaque receiver: the GI techniques gather per G-buffer pixel, not per layer); its radiance (per
// unit alpha, of the frame's radiance AOV) replaces the node's depth and colour: node = (L.r, L.g,
// L.b, alpha as before).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "shared/types.h"
#include "dsm/bindings.h"
#include "core/lights.glsl"
#include "core/reconstruct.glsl"

layout(local_size_x = 64) in;

layout(set = 0, binding = OIT_SHADE_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = OIT_SHADE_LIGHTS, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = OIT_SHADE_LAYERS, std430) readonly buffer Layers { uvec4 header; uvec2 entries[]; } layers;
layout(set = 0, binding = OIT_SHADE_NODES, std430) buffer Nodes { uvec4 nodes[]; };
layout(set = 0, binding = OIT_SHADE_NORMALS, std430) readonly buffer Normals { uint normals[]; };
layout(set = 0, binding = OIT_SHADE_INDIRECT) uniform sampler2D indirectIrradiance;  // GI (frame.giValid != 0)
layout(set = 0, binding = OIT_SHADE_SKY_IRRADIANCE) uniform sampler2D skyIrradiance;  // 1x1 black without a sky
layout(set = 0, binding = OIT_SHADE_SHADOW_PARAMS) uniform Params { GpuShadowParams params; };
layout(set = 0, binding = OIT_SHADE_SHADOW_LAYERS, std430) readonly buffer ShadowLayers { GpuShadowLayer shadowLayers[]; };
// 8-11: the deep shadow maps (dsm/dsm_lookup.glsl)
layout(set = 0, binding = OIT_SHADE_SHADOW_DEPTH) uniform sampler2DArray shadowDepth;
layout(set = 0, binding = OIT_SHADE_SHADOW_MOMENTS) uniform sampler2DArray shadowMoments;
layout(set = 0, binding = OIT_SHADE_SHADOW_LIGHTS, std430) readonly buffer ShadowLights { GpuShadowLight shadowLights[]; };
layout(set = 0, binding = OIT_SHADE_HAIR_SHADOW, std430) readonly buffer HairShadow { float hairShadow[]; };
layout(set = 0, binding = OIT_SHADE_HAIR_POINTS, std430) readonly buffer Points { GpuHairPoint points[]; };

#include "shadow/project.glsl"
#include "shadow/moments.glsl"
#include "shadow/pcf.glsl"
#include "shadow/visibility.glsl"
#include "dsm/dsm_lookup.glsl"
#include "dsm/layer_shadow.glsl"
#include "dsm/kajiya_kay.glsl"
#include "dsm/octahedral.glsl"

// Whether oit_hair_shadow.comp gave the hair points light i's shadow (it has a DSM and a slot).
bool hasStrandShadow(uint i) {
    return dsmLights[i].layer >= 0 && i < uint(hairShadow.length()) / uint(points.length());
}

// The shadow of light i (with a DSM) at hair fragment p of `segment` (its first point's index): the
// strand's own at the segment's two points (oit_hair_shadow.comp), interpolated at p's projection.
float strandShadow(uint i, vec3 p, uint segment) {
    vec3 a = points[segment].position, ab = points[segment + 1u].position - a;
    float s = clamp(dot(p - a, ab) / max(dot(ab, ab), 1e-30), 0.0, 1.0);
    uint first = i * uint(points.length()) + segment;
    return mix(hairShadow[first], hairShadow[first + 1u], s);
}

// Direct radiance towards the eye of one translucent fragment (per unit alpha); `segment`: a hair
// fragment's (OIT_NOT_HAIR: a mesh's).
vec3 directRadiance(vec3 p, vec3 n, uint segment, vec3 albedo, float angle) {
    bool hair = segment != OIT_NOT_HAIR;
    vec3 toEye = normalize(frame.eye - p);
    if (!hair && dot(n, toEye) < 0.0) n = -n;  // two-sided: shade the side the camera sees
    vec3 sum = vec3(0.0);
    for (uint i = 0; i < frame.lightCount; ++i) {
        GpuLight light = lights[i];
        vec3 l;
        vec3 e = incidentIrradiance(light, p, l);
        float ndotl = hair ? 1.0 : max(dot(n, l), 0.0);
        if (ndotl <= 0.0 || all(equal(e, vec3(0.0)))) continue;
        float v = hair && hasStrandShadow(i) ? strandShadow(i, p, segment) : layerShadow(i, light, p, n, l, hair, angle);
        sum += e * v * (hair ? kajiyaKay(albedo, n, l, toEye) : albedo / PI * ndotl);
    }
    return sum;
}

void main() {
    uint index = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64u + gl_LocalInvocationIndex;
    uint aov = frame.aov;
    if (index >= layers.header.x || (aov != AOV_FINAL && aov != AOV_DIRECT && aov != AOV_INDIRECT)) return;
    uvec2 entry = layers.entries[index];
    ivec2 pixel = ivec2(entry.y & 0xFFFFu, entry.y >> 16);
    uvec4 data = nodes[entry.x];
    vec2 ba = unpackHalf2x16(data.w);
    vec3 albedo = vec3(unpackHalf2x16(data.y), ba.x);
    vec3 n = octDecode(unpackSnorm2x16(normals[entry.x]));
    vec3 p = pixelWorldPosition(frame, pixel, uintBitsToFloat(data.x));
    vec3 l = vec3(0.0);
    if (aov != AOV_INDIRECT) l += directRadiance(p, n, data.z, albedo, kernelAngle(pixel));
    // The sky's light as the pixel's opaque surface (or, over the background, an open upward one) sees it.
    if (aov != AOV_INDIRECT)
        l += albedo / PI * texelFetch(skyIrradiance, min(pixel, textureSize(skyIrradiance, 0) - 1), 0).rgb;
    if (aov != AOV_DIRECT && frame.giValid != 0u) l += albedo / PI * texelFetch(indirectIrradiance, pixel, 0).rgb;
    nodes[entry.x] = uvec4(floatBitsToUint(l.r), floatBitsToUint(l.g), floatBitsToUint(l.b), data.w);
}
