#version 460
// The sky's bounce: every camera surfel (lpv/camera_surfel.glsl) lit by the visible sky
// (names::kSkyIrradiance) becomes a VPL of reflected flux albedo * E * area, written after the RSM's
// VPLs so that lpv/inject_range.comp and lpv/inject.comp take both together. Its area in the VPL is 0:
// what blocks light, the camera's surfels inject themselves (lpv/inject_camera.comp).
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "lpv/bindings.h"
#include "core/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = LPV_SKY_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = LPV_SKY_GBUFFER_ALBEDO) uniform sampler2D gAlbedo;
layout(set = 0, binding = LPV_SKY_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = LPV_SKY_GBUFFER_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = LPV_SKY_IRRADIANCE) uniform sampler2D skyIrradiance;
layout(set = 0, binding = LPV_SKY_VPLS, std430) writeonly buffer Vpls { GpuVpl vpls[]; };
layout(push_constant) uniform Push { LpvPush pc; };

#include "lpv/camera_surfel.glsl"

void main() {
    const int step = int(pc.cameraGeometryStep);
    const uvec2 blocks = (uvec2(frame.width, frame.height) + uint(step) - 1u) / uint(step);
    if (any(greaterThanEqual(gl_GlobalInvocationID.xy, blocks))) return;
    const uint first = pc.layerCount * pc.vplResolution * pc.vplResolution;  // after the RSM's
    const uint index = first + gl_GlobalInvocationID.y * blocks.x + gl_GlobalInvocationID.x;
    const CameraSurfel s = cameraSurfel(gl_GlobalInvocationID.xy, step);
    GpuVpl v;
    v.position = s.x;
    v.exists = s.valid ? 1u : 0u;
    v.normal = s.n;
    v.area = 0.0;
    v.flux = vec3(0.0);
    v.pad0 = 0u;
    if (s.valid)
        v.flux = texelFetch(gAlbedo, s.pixel, 0).rgb * texelFetch(skyIrradiance, s.pixel, 0).rgb * s.area;
    vpls[index] = v;
}
