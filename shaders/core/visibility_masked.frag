#version 460
// Visibility ID for alphaMode MASK materials: the alpha test stays in the raster (core/visibility.frag).
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "core/material.glsl"

layout(location = 1) in vec2 inUv;
layout(location = 3) flat in uint inIdBase;
layout(push_constant) uniform Push { DrawPush draw; };  // ShadowDrawPush starts alike (material)
layout(location = 0) out uint outId;

void main() {
    if (alphaDiscarded(draw.material, baseColor(draw.material, inUv).a)) discard;
    outId = inIdBase + uint(gl_PrimitiveID) + 1u;
}
