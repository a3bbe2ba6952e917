#version 460
// Reflective shadow map (Dachsbacher & Stamminger 2005): per light texel, the surface normal and the
// flux it reflects. The texel's footprint perpendicular to the light is A = t^2 for an orthographic
// map (t = texel world size) and A = t^2 z^2 cos(a) for a perspective one (t per unit depth, z the
// depth along the axis, a the angle off the axis: the texel's solid angle t^2 cos^3(a) times d^2).
// The flux through it is E_perp * A, and the surface reflects albedo times that (Lambertian).
// World position is not stored: the gather reconstructs it from the RSM depth.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "render/material.glsl"
#include "render/lights.glsl"
#include "shared/octahedral.glsl"

layout(set = 0, binding = 3, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = 4, std430) readonly buffer Layers { GpuRsmLayer rsmLayers[]; };
layout(push_constant) uniform Push { RsmDrawPush draw; };

layout(location = 0) in vec3 inNormal;
layout(location = 1) in vec2 inUv;
layout(location = 2) in vec3 inWorld;

layout(location = 0) out vec2 outNormal;
layout(location = 1) out vec4 outFlux;

void main() {
    vec4 c = baseColor(draw.material, inUv);
    if (alphaDiscarded(draw.material, c.a)) discard;
    GpuLight light = lights[draw.light];
    GpuRsmLayer layer = rsmLayers[draw.layer];
    vec3 l;
    vec3 e = incidentIrradiance(light, inWorld, l);
    float t = layer.params.x;
    float area = t * t;
    if (layer.params.y > 0.5) {  // the layer's own axis (spot cone, or a point light's cube face)
        float z = (layer.viewProj * vec4(inWorld, 1.0)).w;
        area *= z * z * clamp(z / max(length(inWorld - light.position.xyz), 1e-6), 0.0, 1.0);
    }
    vec3 n = normalize(inNormal);
    if (dot(n, l) < 0.0) n = -n;  // the side the light sees (two-sided surfaces)
    outNormal = octEncode(n);
    outFlux = vec4(c.rgb * e * area, 1.0);
}
