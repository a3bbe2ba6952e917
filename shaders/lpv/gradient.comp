#version 460
// LPV temporal gradients (core/names.h GiChange): per block of LPV_CHANGE_BLOCK x LPV_CHANGE_BLOCK
// pixels, the irradiance at the block's centre receiver from the kept volume (last frame's sum, at
// last frame's cascade placement) and from this frame's, and their luminances' change. The LPV has no
// sampling noise: a still light gives bit-identical volumes, so its change is exactly 0, and a
// light's change shows whole (shared/gi_change.glsl), or 0 where the centre pixel holds no surface.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "lpv/bindings.h"
#include "core/reconstruct.glsl"
#include "shared/gi_change.glsl"
#include "shared/luminance.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = LPV_GRADIENT_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = LPV_GRADIENT_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = LPV_GRADIENT_GBUFFER_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = LPV_GRADIENT_SUM, std430) readonly buffer Accumulated { vec4 accum[]; };
layout(set = 0, binding = LPV_GRADIENT_KEPT_SUM, std430) readonly buffer KeptSum { vec4 keptAccum[]; };
layout(set = 0, binding = LPV_GRADIENT_KEPT_CASCADES) uniform KeptCascades {
    GpuLpvCascade keptCascades[LPV_MAX_CASCADES];
};
layout(set = 0, binding = LPV_GRADIENT_CHANGE, rgba32f) uniform writeonly image2D outChange;
layout(push_constant) uniform Push { LpvPush pc; };

#include "lpv/sh.glsl"
#include "lpv/volume.glsl"

// Volume 0: this frame's; 1: the kept one (same resolution and cascade count, lpv.cpp).
const uint kNow = 0u, kKept = 1u;
// Member-wise: the push block's and the uniform block's structs are different types in SPIR-V.
GpuLpvCascade lpvCascade(uint v, uint k) {
    if (v == kNow) return GpuLpvCascade(pc.cascades[k].origin, pc.cascades[k].cellSize);
    return GpuLpvCascade(keptCascades[k].origin, keptCascades[k].cellSize);
}
vec4 lpvSum(uint v, uint index) { return v == kNow ? accum[index] : keptAccum[index]; }
#include "lpv/irradiance.glsl"

void main() {
    const ivec2 block = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(block, imageSize(outChange)))) return;
    const ivec2 pixel = min(block * LPV_CHANGE_BLOCK + LPV_CHANGE_BLOCK / 2, ivec2(frame.width, frame.height) - 1);
    vec3 x, n;
    bool hair;
    vec4 change = vec4(0.0);
    if (lpvReceiver(pixel, x, n, hair)) {
        change = giChangeTexel(luminance(lpvIrradiance(kNow, x, n, hair)), luminance(lpvIrradiance(kKept, x, n, hair)));
    }
    imageStore(outChange, block, change);
}
