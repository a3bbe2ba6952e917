#version 460
// LPV final gather: per pixel the irradiance of the summed volume (lpv/irradiance.glsl: trilinear,
// one cell out along the normal, cascades summed). Debug modes show a volume slice.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "lpv/bindings.h"
#include "core/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = LPV_GATHER_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = LPV_GATHER_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = LPV_GATHER_GBUFFER_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = LPV_GATHER_SUM, std430) readonly buffer Accumulated { vec4 accum[]; };
layout(set = 0, binding = LPV_GATHER_GEOMETRY, std430) readonly buffer GeometryVolume { vec4 geometry[]; };
layout(set = 0, binding = LPV_GATHER_IRRADIANCE, rgba32f) uniform writeonly image2D outIrradiance;
layout(push_constant) uniform Push { LpvPush pc; };

#include "lpv/sh.glsl"
#include "lpv/volume.glsl"

// The gather reads one volume, this frame's.
GpuLpvCascade lpvCascade(uint v, uint k) { return pc.cascades[k]; }
vec4 lpvSum(uint v, uint index) { return accum[index]; }
#include "lpv/irradiance.glsl"

// Debug slice of cascade 0: the image spans the slice; light shows mean intensity, geometry the
// peak blocking.
vec3 slice(ivec2 pixel) {
    uint axis = pc.sliceAxis;
    vec2 uv = (vec2(pixel) + 0.5) / vec2(frame.width, frame.height);
    ivec2 p = ivec2(uv * float(pc.resolution));
    ivec3 c = axis == 0u ? ivec3(pc.sliceIndex, p.x, p.y) : axis == 1u ? ivec3(p.x, pc.sliceIndex, p.y)
                                                                    : ivec3(p.x, p.y, pc.sliceIndex);
    if (frame.aov == AOV_GV_SLICE) return vec3(geometry[geometryIndex(0u, c)].x * SH_C0 * LOBE_PEAK / (LOBE_C0 * SH_C0));
    return vec3(accum[lightIndex(0u, 0u, c)].x, accum[lightIndex(0u, 1u, c)].x, accum[lightIndex(0u, 2u, c)].x) * SH_C0;
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(frame.width, frame.height)))) return;
    vec3 e = vec3(0.0);
    if (frame.aov == AOV_LPV_SLICE || frame.aov == AOV_GV_SLICE) {
        e = slice(pixel);
    } else {
        vec3 x, n;
        bool hair;
        if (lpvReceiver(pixel, x, n, hair)) e = lpvIrradiance(0u, x, n, hair);
    }
    imageStore(outIrradiance, pixel, vec4(e, 1.0));
}
