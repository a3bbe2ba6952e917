#version 460
// Dual-paraboloid depth pass, vertex stage: world position and the hemisphere (instance) only; the
// paraboloid mapping is not linear, so it is applied after tessellation (paraboloid.tese).
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "core/instances.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 2) in vec2 inUv;

layout(location = 0) out vec3 outWorld;
layout(location = 1) out vec2 outUv;
layout(location = 2) flat out int outInstance;

void main() {
    outWorld = instanceWorld(sceneInstance(2), inPosition);
    outUv = inUv;
    outInstance = instanceLayer(2);  // the hemisphere
}
