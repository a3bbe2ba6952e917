#version 460
// Camera translucency resolve, one thread per pixel, after the lighting pass: the pixel's list of
// hair and BLEND fragments (dsm/oit_insert.glsl) is sorted (its OIT_MAX_LIST nearest), each fragment
// is lit like an opaque surface (every light with its shadow-map filter and its deep shadow map,
// Lambert or Kajiya-Kay, plus the indirect irradiance gathered at the pixel) and the fragments are
// composited front to back over the lit opaque image ("hdr", read and written in place):
//   C = sum_i T_i a_i L_i,  T_i = prod_{j<i} (1 - a_j),  out = C + T_n x opaque.
// Fragments beyond OIT_MAX_LIST are merged into one layer behind the kept ones (their combined alpha,
// the last kept fragment's radiance). Only the radiance AOVs (final, direct, indirect) are composited;
// the others keep the opaque surface.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "shared/types.h"
#include "render/lights.glsl"
#include "render/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = 1, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = 2, std430) readonly buffer Heads { uint heads[]; };
layout(set = 0, binding = 3, std430) readonly buffer Nodes { uvec4 nodes[]; };
layout(set = 0, binding = 4, std430) readonly buffer Normals { uint normals[]; };
layout(set = 0, binding = 5, std430) buffer Stats { OitStats stats; };
layout(set = 0, binding = 6, rgba32f) uniform image2D hdr;
layout(set = 0, binding = 7) uniform sampler2D indirectIrradiance;  // GI (frame.options.x != 0)
// 8-11: the deep shadow maps (dsm/dsm_lookup.glsl)
layout(set = 0, binding = 12) uniform sampler2DArray shadowDepth;
layout(set = 0, binding = 13) uniform sampler2DArray shadowMoments;
layout(set = 0, binding = 14, std430) readonly buffer Layers { GpuShadowLayer shadowLayers[]; };
layout(set = 0, binding = 15, std430) readonly buffer ShadowLights { GpuShadowLight shadowLights[]; };
layout(set = 0, binding = 16) uniform Params { GpuShadowParams params; };
layout(push_constant) uniform Push { OitPush pc; };

#include "shadow/project.glsl"
#include "shadow/moments.glsl"
#include "shadow/pcf.glsl"
#include "shadow/visibility.glsl"
#include "dsm/dsm_lookup.glsl"
#include "dsm/kajiya_kay.glsl"
#include "dsm/octahedral.glsl"

#define SORT_CAPACITY OIT_MAX_LIST
#define SORT_CHAINS DSM_CHAINS
// The walk that sorts a pixel's list also sums the log-transmittance of all its fragments, so that
// the merged tail (the fragments beyond the kept ones) needs no second walk: its transmittance is
// exp(all - kept). Clamped so that an opaque fragment (alpha 1) stays finite.
float logTransmittanceAll;
float logTransmittance(float alpha) { return log(max(1.0 - alpha, 1e-7)); }
vec2 sortEntry(uint n, uvec4 node) {  // (depth, node)
    logTransmittanceAll += logTransmittance(abs(unpackHalf2x16(node.w).y));
    return vec2(uintBitsToFloat(node.x), uintBitsToFloat(n));
}
// Equal depths (read only then): by the fragment's tangent or normal, colour and alpha.
uint sortTieKey(vec2 e) {
    uint n = floatBitsToUint(e.y);
    return normals[n] ^ (nodes[n].w * 0x9E3779B9u) ^ (nodes[n].y * 0x85EBCA6Bu);
}
#include "dsm/sort_nearest.glsl"

shared uint groupKept, groupDropped, groupLongest;

// Direct radiance towards the eye of one translucent fragment (per unit alpha).
vec3 directRadiance(vec3 p, vec3 n, bool hair, vec3 albedo, float angle) {
    vec3 toEye = normalize(frame.cameraPos.xyz - p);
    if (!hair && dot(n, toEye) < 0.0) n = -n;  // two-sided: shade the side the camera sees
    vec3 sum = vec3(0.0);
    for (uint i = 0; i < frame.size.z; ++i) {
        GpuLight light = lights[i];
        vec3 l;
        vec3 e = incidentIrradiance(light, p, l);
        float ndotl = hair ? 1.0 : max(dot(n, l), 0.0);
        if (ndotl <= 0.0 || all(equal(e, vec3(0.0)))) continue;
        float v = 1.0;
        if (light.radiance.w != NO_SHADOW)
            v = lightVisibility(shadowLights[uint(light.radiance.w)], light, p, hair ? l : n, angle, true).x;
        v *= deepShadowTransmittance(i, p, n, hair);
        sum += e * v * (hair ? kajiyaKay(albedo, n, l, toEye) : albedo / PI * ndotl);
    }
    return sum;
}

void main() {
    if (gl_LocalInvocationIndex == 0) groupKept = groupDropped = groupLongest = 0u;
    barrier();
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    uint aov = frame.size.w;
    bool radianceAov = aov == AOV_FINAL || aov == AOV_DIRECT || aov == AOV_INDIRECT;
    uint chains[DSM_CHAINS];
    bool listed = false;
    [[unroll]] for (int k = 0; k < DSM_CHAINS; ++k) {
        chains[k] = all(lessThan(pixel, ivec2(pc.sizes.xy))) ? heads[(pixel.y * pc.sizes.x + pixel.x) * DSM_CHAINS + k] : DSM_NONE;
        listed = listed || chains[k] != DSM_NONE;
    }
    if (listed) {
        uint count;
        logTransmittanceAll = 0.0;
        uint length = sortNearest(chains, OIT_MAX_LIST, pc.sizes.z, count);
        atomicAdd(groupKept, count);
        atomicAdd(groupDropped, length - count);
        atomicMax(groupLongest, length);
        if (radianceAov) {
            vec3 irradiance = frame.options.x != 0u ? texelFetch(indirectIrradiance, pixel, 0).rgb : vec3(0.0);
            float angle = kernelAngle(pixel);
            vec3 sum = vec3(0.0), last = vec3(0.0);
            float t = 1.0, logKept = 0.0;
            for (uint i = 0; i < count; ++i) {
                uint node = floatBitsToUint(sorted[i].y);
                uvec4 data = nodes[node];
                vec2 ba = unpackHalf2x16(data.w);
                vec3 albedo = vec3(unpackHalf2x16(data.y), ba.x);
                bool hair = ba.y < 0.0;
                float a = abs(ba.y);
                vec3 n = octDecode(unpackSnorm2x16(normals[node]));
                vec3 p = pixelWorldPosition(frame, pixel, sorted[i].x);
                vec3 l = vec3(0.0);
                // The indirect irradiance is the opaque receiver's at this pixel (an approximation:
                // the GI techniques gather per G-buffer pixel, not per translucent layer).
                if (aov != AOV_INDIRECT) l += directRadiance(p, n, hair, albedo, angle);
                if (aov != AOV_DIRECT) l += albedo / PI * irradiance;
                sum += t * a * l;
                t *= 1.0 - a;
                logKept += logTransmittance(a);
                last = l;
            }
            // Fragments beyond the cap (all behind the last kept one) are not dropped: they are
            // composited as one layer of their combined alpha with the last kept fragment's radiance.
            if (length > count) {
                float tail = min(exp(logTransmittanceAll - logKept), 1.0);
                sum += t * (1.0 - tail) * last;
                t *= tail;
            }
            vec4 opaque = imageLoad(hdr, pixel);
            imageStore(hdr, pixel, vec4(sum + t * opaque.rgb, 1.0 - t * (1.0 - opaque.a)));
        }
    }
    barrier();
    if (gl_LocalInvocationIndex == 0 && (groupKept | groupDropped) != 0u) {
        atomicAdd(stats.counts.y, groupKept);
        atomicAdd(stats.counts.z, groupDropped);
        atomicMax(stats.counts.w, groupLongest);
    }
}
