#version 460
// Layered depth pass: one instance per layer of a light (cascades, cube faces, a spot's single
// layer), so that every layer of a light is drawn by one draw call. Instance i uses view row
// viewIndex + i and writes array layer firstLayer + i (gl_Layer from the vertex stage: Vulkan 1.2
// shaderOutputLayer).
#extension GL_GOOGLE_include_directive : require
#extension GL_ARB_shader_viewport_layer_array : require
#include "shared/types.h"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;

layout(set = 0, binding = 0, std430) readonly buffer Views { mat4 viewProj[]; } views;
layout(push_constant) uniform Push { ShadowDrawPush draw; };

layout(location = 0) out vec3 outNormal;
layout(location = 1) out vec2 outUv;

void main() {
    gl_Position = views.viewProj[draw.viewIndex + gl_InstanceIndex] * vec4(inPosition, 1.0);
    gl_Layer = int(draw.firstLayer) + gl_InstanceIndex;
    outNormal = inNormal;
    outUv = inUv;
}
