#version 460
// The deep shadow maps' transmittance at every hair point (dsm.strands), for each light with a map:
// the camera's hair fragments interpolate it along their segment (dsm/oit_shade.comp) instead of
// filtering the map themselves. A strand's points are 4.4x fewer than its camera fragments at 25k
// strands (675k against 3.0M kept layers at 1080p), and the filtered lookup was most of the shade
// pass's cost. Slot k of light i (GpuDsmLight.opacity.z) holds its values at k x points + point.
// The points come in the order of a Morton curve (HairGpu::spatialPoints), so that a warp's taps
// fall on neighbouring texels: a strand's consecutive points lie many texels apart, and in the points'
// own order the pass took 0.66 ms at 25k strands on the H100.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "shared/types.h"

layout(local_size_x = 64) in;

layout(set = 0, binding = 0) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = 3, std430) readonly buffer Points { GpuHairPoint points[]; };
layout(set = 0, binding = 5, std430) writeonly buffer Transmittance { float strandTransmittance[]; };
layout(set = 0, binding = 6, std430) readonly buffer Spatial { uint spatialPoints[]; };
// 8-11: the deep shadow maps (dsm/dsm_lookup.glsl)

#include "dsm/dsm_lookup.glsl"

void main() {
    uint t = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64u + gl_LocalInvocationIndex;
    if (t >= uint(spatialPoints.length())) return;
    uint point = spatialPoints[t], count = uint(points.length());
    GpuHairPoint p = points[point];
    for (uint light = 0; light < frame.size.z; ++light) {
        GpuDsmLight dsm = dsmLights[light];
        if (dsm.params.z < 0.0) continue;
        strandTransmittance[uint(dsm.opacity.z) * count + point] =
            deepShadowTransmittance(light, p.position.xyz, p.tangent.xyz, true);
    }
}
