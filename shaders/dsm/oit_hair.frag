#version 460
// Camera translucency build for hair ribbons (dsm/hair.vert in the camera's view): a strand thinner
// than a pixel is drawn one pixel wide and passes its coverage on as alpha (opacity x width / drawn).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#include "shared/types.h"

layout(push_constant) uniform Push { OitBuildPush draw; };
layout(location = 0) in vec3 inTangent;
layout(location = 1) in vec3 inColor;
layout(location = 2) in float inAlpha;
layout(location = 5) flat in uint inSegment;  // the provoking vertex's point: the segment's first

#include "dsm/oit_insert.glsl"

void main() { oitInsert(ivec2(gl_FragCoord.xy), gl_FragCoord.z, inColor, inAlpha, normalize(inTangent), inSegment); }
