#version 460
// Dual-paraboloid depth pass, tessellation evaluation: interpolate the world position on the flat
// triangle, then map it to the hemisphere's disc. Geometry beyond the rim is clipped by a clip
// distance (the rim is a cone around the axis, not a plane of clip space).
#extension GL_GOOGLE_include_directive : require
#extension GL_ARB_shader_viewport_layer_array : require
#include "shared/types.h"
#include "core/scene_bindings.h"
#include "shadow/paraboloid.glsl"

layout(triangles, equal_spacing, cw) in;
layout(set = 0, binding = SCENE_VIEWS, std430) readonly buffer Views { mat4 viewProj[]; } views;
layout(push_constant) uniform Push { ShadowDrawPush draw; };

layout(location = 0) in vec3 inWorld[];
layout(location = 1) in vec2 inUv[];
layout(location = 2) flat in int inInstance[];
layout(location = 0) out vec3 outNormal;  // unused by the fragment stage, kept for its interface
layout(location = 1) out vec2 outUv;

out float gl_ClipDistance[1];

void main() {
    vec3 b = gl_TessCoord;
    vec3 world = b.x * inWorld[0] + b.y * inWorld[1] + b.z * inWorld[2];
    outUv = b.x * inUv[0] + b.y * inUv[1] + b.z * inUv[2];
    outNormal = vec3(0.0);
    int instance = inInstance[0];
    vec3 v = (views.viewProj[draw.viewIndex + instance] * vec4(world, 1.0)).xyz;
    gl_Position = vec4(paraboloidProject(v, draw.paraboloidNear, draw.paraboloidFar, draw.paraboloidDiscScale), 1.0);
    gl_ClipDistance[0] = -v.z / max(length(v), 1e-20) - paraboloidRimCos(draw.paraboloidDiscScale);
    gl_Layer = int(draw.firstLayer) + instance;
}
