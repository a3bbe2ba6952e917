#version 460
// DSM build for alphaMode BLEND meshes (drawn with core/scene.vert): alpha is the material's
// base-colour alpha (factor x texture).
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "core/material.glsl"
#include "dsm/dsm_common.glsl"

layout(push_constant) uniform Push { DsmBuildPush draw; };
layout(location = 1) in vec2 inUv;
layout(location = 2) in vec3 inWorld;

#include "dsm/dsm_insert.glsl"

void main() {
    float depth = dsmDepth(draw.view.viewer, draw.view.viewerIsPoint, inWorld);
    dsmInsert(uvec2(gl_FragCoord.xy), depth, baseColor(draw.material, inUv).a, inWorld);
}
