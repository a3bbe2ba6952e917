#version 460
// DSM build for hair ribbons: depth and alpha come interpolated from the vertex stage.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(push_constant) uniform Push { DsmBuildPush draw; };
layout(location = 2) in float inAlpha;
layout(location = 3) in float inDepth;
layout(location = 4) in vec3 inWorld;

#include "dsm/dsm_insert.glsl"

void main() { dsmInsert(uvec2(gl_FragCoord.xy), inDepth, inAlpha, inWorld); }
