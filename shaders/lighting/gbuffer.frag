#version 460
// Thin G-buffer pass: albedo (sRGB attachment) and world normal; all lighting is in compute.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "core/material.glsl"

layout(location = 0) in vec3 inNormal;
layout(location = 1) in vec2 inUv;
layout(push_constant) uniform Push { DrawPush draw; };

layout(location = 0) out vec4 outAlbedo;
layout(location = 1) out vec4 outNormal;

void main() {
    vec4 c = baseColor(draw.material, inUv);
    if (alphaDiscarded(draw.material, c.a)) discard;
    // Geometry is drawn without culling; the lighting pass turns normals towards the viewer.
    vec3 n = normalize(inNormal);
    outAlbedo = vec4(c.rgb, 1.0);
    outNormal = vec4(n, 1.0);
}
