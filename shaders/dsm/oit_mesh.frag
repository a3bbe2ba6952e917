#version 460
// Camera translucency build for alphaMode BLEND meshes (core/scene.vert): base colour and alpha
// (factor x texture), the interpolated normal.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#include "shared/types.h"
#include "core/material.glsl"

layout(push_constant) uniform Push { OitBuildPush draw; };
layout(location = 0) in vec3 inNormal;
layout(location = 1) in vec2 inUv;

#include "dsm/oit_insert.glsl"

void main() {
    vec4 c = baseColor(draw.material, inUv);
    oitInsert(ivec2(gl_FragCoord.xy), gl_FragCoord.z, c.rgb, c.a, normalize(inNormal), OIT_NOT_HAIR);
}
