#version 460
// Dual-paraboloid depth pass, tessellation control: straight edges become curves under the
// paraboloid mapping, so each edge is split until it spans at most `maxEdgeAngle` radians as seen
// from the light (small pieces, whose straight edges are then sub-texel accurate). Triangles
// entirely behind the hemisphere's rim are dropped here (tessellation level 0).
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "core/scene_bindings.h"
#include "shadow/paraboloid.glsl"

layout(vertices = 3) out;
layout(set = 0, binding = SCENE_VIEWS, std430) readonly buffer Views { mat4 viewProj[]; } views;
layout(push_constant) uniform Push { ShadowDrawPush draw; };

layout(location = 0) in vec3 inWorld[];
layout(location = 1) in vec2 inUv[];
layout(location = 2) flat in int inInstance[];
layout(location = 0) out vec3 outWorld[];
layout(location = 1) out vec2 outUv[];
layout(location = 2) flat out int outInstance[];

float edgeLevel(vec3 a, vec3 b) {
    float angle = acos(clamp(dot(normalize(a), normalize(b)), -1.0, 1.0));
    return clamp(ceil(angle / draw.maxEdgeAngle), 1.0, 64.0);
}

void main() {
    outWorld[gl_InvocationID] = inWorld[gl_InvocationID];
    outUv[gl_InvocationID] = inUv[gl_InvocationID];
    outInstance[gl_InvocationID] = inInstance[gl_InvocationID];
    if (gl_InvocationID != 0) return;
    mat4 view = views.viewProj[draw.viewIndex + inInstance[0]];
    vec3 v0 = (view * vec4(inWorld[0], 1.0)).xyz, v1 = (view * vec4(inWorld[1], 1.0)).xyz,
         v2 = (view * vec4(inWorld[2], 1.0)).xyz;
    float rim = paraboloidRimCos(draw.paraboloidDiscScale);
    // Behind the rim: every vertex beyond it. The region beyond the rim is a convex cone (the rim is
    // past 90 degrees), so such a triangle lies wholly inside it.
    bool behind = -v0.z < rim * length(v0) && -v1.z < rim * length(v1) && -v2.z < rim * length(v2);
    // Outer level i belongs to the edge opposite vertex i.
    float l0 = behind ? 0.0 : edgeLevel(v1, v2);
    float l1 = behind ? 0.0 : edgeLevel(v2, v0);
    float l2 = behind ? 0.0 : edgeLevel(v0, v1);
    gl_TessLevelOuter[0] = l0;
    gl_TessLevelOuter[1] = l1;
    gl_TessLevelOuter[2] = l2;
    gl_TessLevelInner[0] = max(l0, max(l1, l2));
}
