#version 460
// Camera translucency: the shadow of every light with a deep shadow map at every drawn hair point
// (opaque map x DSM, dsm/layer_shadow.glsl), which oit_shade.comp interpolates along each hair
// layer's segment instead of filtering both maps per layer: at 25k strands a strand's points are
// 4.4x fewer than its camera layers (675k against 3.0M at 1080p), and the two lookups were most of
// the shade pass. The points come in the order of a Morton curve (HairGpu::spatialPoints), so that a
// warp's taps fall on neighbouring texels: a strand's consecutive points lie many texels apart, and in
// their own order the lookups scatter over the whole map. Light i's values are at i x points + point (lights without a DSM: not written, the shade
// pass filters their maps per layer).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "shared/types.h"
#include "dsm/bindings.h"
#include "core/lights.glsl"

layout(local_size_x = 64) in;

layout(set = 0, binding = OIT_SHADE_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = OIT_SHADE_LIGHTS, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = OIT_SHADE_SHADOW_PARAMS) uniform Params { GpuShadowParams params; };
layout(set = 0, binding = OIT_SHADE_SHADOW_LAYERS, std430) readonly buffer ShadowLayers { GpuShadowLayer shadowLayers[]; };
// 8-11: the deep shadow maps (dsm/dsm_lookup.glsl)
layout(set = 0, binding = OIT_SHADE_SHADOW_DEPTH) uniform sampler2DArray shadowDepth;
layout(set = 0, binding = OIT_SHADE_SHADOW_MOMENTS) uniform sampler2DArray shadowMoments;
layout(set = 0, binding = OIT_SHADE_SHADOW_LIGHTS, std430) readonly buffer ShadowLights { GpuShadowLight shadowLights[]; };
layout(set = 0, binding = OIT_SHADE_HAIR_SHADOW, std430) writeonly buffer HairShadow { float hairShadow[]; };
layout(set = 0, binding = OIT_SHADE_HAIR_POINTS, std430) readonly buffer Points { GpuHairPoint points[]; };
layout(set = 0, binding = OIT_HAIR_SHADOW_SPATIAL, std430) readonly buffer Spatial { uint spatialPoints[]; };

#include "shadow/project.glsl"
#include "shadow/moments.glsl"
#include "shadow/pcf.glsl"
#include "shadow/visibility.glsl"
#include "dsm/dsm_lookup.glsl"
#include "dsm/layer_shadow.glsl"

void main() {
    uint t = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64u + gl_LocalInvocationIndex;
    if (t >= uint(spatialPoints.length())) return;
    uint point = spatialPoints[t], count = uint(points.length());
    GpuHairPoint p = points[point];
    // The filter kernel's rotation: a golden-ratio sequence along each strand's points.
    float angle = 6.28318531 * fract(float(point) * 0.618034);
    uint lightCount = min(frame.lightCount, uint(hairShadow.length()) / count);
    for (uint i = 0; i < lightCount; ++i) {
        if (dsmLights[i].layer < 0) continue;
        GpuLight light = lights[i];
        vec3 l;
        incidentIrradiance(light, p.position, l);
        hairShadow[i * count + point] = layerShadow(i, light, p.position, p.tangent, l, true, angle);
    }
}
