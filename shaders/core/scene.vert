#version 460
// Shared by the G-buffer, RSM and DSM passes: mesh vertices moved to the world by their instance
// (gl_InstanceIndex), one view matrix per pass.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "core/instances.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;

layout(set = 0, binding = SCENE_VIEWS, std430) readonly buffer Views { mat4 viewProj[]; } views;
layout(push_constant) uniform Push { DrawPush draw; };

layout(location = 0) out vec3 outNormal;
layout(location = 1) out vec2 outUv;
layout(location = 2) out vec3 outWorld;
layout(location = 3) flat out uint outIdBase;  // visibility ID base (core/visibility.glsl)

void main() {
    const vec3 world = instanceWorld(gl_InstanceIndex, inPosition);
    gl_Position = views.viewProj[draw.viewIndex] * vec4(world, 1.0);
    outNormal = instanceNormal(gl_InstanceIndex, inNormal);
    outUv = inUv;
    outWorld = world;
    outIdBase = instances[gl_InstanceIndex].firstDrawnTriangle + draw.triangleBase;
}
