#version 460
// Depth-only shadow pass for alphaMode MASK materials: discard cut-out texels, write nothing else.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "core/material.glsl"

layout(location = 0) in vec3 inNormal;
layout(location = 1) in vec2 inUv;
layout(push_constant) uniform Push { ShadowDrawPush draw; };

void main() {
    if (alphaDiscarded(draw.material, baseColor(draw.material, inUv).a)) discard;
}
