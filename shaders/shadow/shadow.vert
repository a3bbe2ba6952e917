#version 460
// Layered depth pass: one instance per layer of a light (cascades, cube faces, a spot's single
// layer), so that every layer of a light is drawn by one draw call (per run of scene instances:
// core/instances.glsl). Layer i uses view row
// viewIndex + i and writes array layer firstLayer + i (gl_Layer from the vertex stage: Vulkan 1.2
// shaderOutputLayer).
#extension GL_GOOGLE_include_directive : require
#extension GL_ARB_shader_viewport_layer_array : require
#include "shared/types.h"
#include "core/instances.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;

layout(set = 0, binding = SCENE_VIEWS, std430) readonly buffer Views { mat4 viewProj[]; } views;
layout(push_constant) uniform Push { ShadowDrawPush draw; };

layout(location = 0) out vec3 outNormal;
layout(location = 1) out vec2 outUv;
layout(location = 3) flat out uint outIdBase;  // visibility ID base (core/visibility.glsl)

void main() {
    const int layers = int(draw.layerCount), instance = sceneInstance(layers), layer = instanceLayer(layers);
    gl_Position = views.viewProj[draw.viewIndex + layer] * vec4(instanceWorld(instance, inPosition), 1.0);
    gl_Layer = int(draw.firstLayer) + layer;
    outNormal = instanceNormal(instance, inNormal);
    outUv = inUv;
    outIdBase = instances[instance].firstDrawnTriangle + draw.triangleBase;
}
