#version 460
// RSM indirect gather: for a receiver, sum the irradiance of VPLs around its projection into each
// RSM layer, at the polar sample offsets of Dachsbacher & Stamminger (r_max * xi1 * (sin, cos)(2 pi
// xi2), generated once from a seed on the CPU with their density-compensating weights), or over
// every texel (exact mode, for tests). Writes irradiance; lighting multiplies by albedo / pi.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "render/lights.glsl"
#include "render/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = 1) uniform sampler2D gNormal;
layout(set = 0, binding = 2) uniform sampler2D gDepth;
layout(set = 0, binding = 3) uniform sampler2DArray rsmDepth;
layout(set = 0, binding = 4) uniform sampler2DArray rsmNormal;
layout(set = 0, binding = 5) uniform sampler2DArray rsmFlux;
layout(set = 0, binding = 6, std430) readonly buffer Layers { GpuRsmLayer rsmLayers[]; };
layout(set = 0, binding = 7, std430) readonly buffer Samples { vec4 samples[]; };  // xy offset (uv), z weight
layout(set = 0, binding = 8, rgba32f) uniform writeonly image2D outIrradiance;
layout(set = 0, binding = 9, std430) readonly buffer PixelList { uvec4 header; uvec2 pixels[]; } list;
layout(push_constant) uniform Push { RsmPush pc; };

#include "rsm/vpl.glsl"

vec3 gather(vec3 x, vec3 n) {
    vec3 e = vec3(0.0);
    const int res = int(pc.sizes.z);
    for (uint layer = 0; layer < pc.mode.z; ++layer) {
        if (pc.mode.x == RSM_GATHER_ALL_TEXELS) {
            for (int ty = 0; ty < res; ++ty)
                for (int tx = 0; tx < res; ++tx) e += vplIrradiance(ivec2(tx, ty), layer, x, n);
            continue;
        }
        // The pattern is centred on x's projection. A receiver outside the map has no texel of its
        // own: the disc is centred on the nearest map point and grows with the distance outside, so
        // the result stays continuous across the light frustum's border; a receiver behind a spot
        // light (a ceiling above a downward spot) samples the whole map. Weights scale with the
        // disc's area, so the estimate still converges to the sum over the disc.
        vec4 clip = rsmLayers[layer].viewProj * vec4(x, 1.0);
        vec2 st = vec2(0.5);
        float radius = 0.70710678;
        if (clip.w > 0.0) {
            vec2 p = clip.xy / clip.w * 0.5 + 0.5;
            st = clamp(p, vec2(0.0), vec2(1.0));
            radius = min(pc.params.z + length(p - st), max(pc.params.z, 0.70710678));
        }
        float scale = radius / pc.params.z;
        for (uint i = 0; i < pc.mode.y; ++i) {
            vec4 s = samples[i];
            vec2 uv = st + s.xy * scale;
            if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) continue;
            e += (s.z * scale * scale) * vplIrradiance(ivec2(uv * float(res)), layer, x, n);
        }
    }
    return e;
}

void main() {
    ivec2 out_ = ivec2(gl_GlobalInvocationID.xy);
    ivec2 pixel = out_;
    if (pc.mode.x == RSM_GATHER_LIST) {
        uint index = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * 8u;
        if (index >= list.header.x) return;
        pixel = out_ = ivec2(list.pixels[index]);
    } else {
        if (any(greaterThanEqual(out_, ivec2(pc.sizes.xy)))) return;
        if (pc.mode.x == RSM_GATHER_LOWRES)  // the cell's representative (centre) full-res pixel
            pixel = min(out_ * int(pc.mode.w) + int(pc.mode.w) / 2, ivec2(frame.size.xy) - 1);
    }
    float depth = texelFetch(gDepth, pixel, 0).r;
    vec3 e = vec3(0.0);
    if (depth < 1.0) {
        vec3 x = pixelWorldPosition(frame, pixel, depth);
        vec3 n = normalize(texelFetch(gNormal, pixel, 0).xyz);
        if (dot(n, frame.cameraPos.xyz - x) < 0.0) n = -n;
        e = gather(x, n);
    }
    imageStore(outIrradiance, out_, vec4(e, 1.0));
}
