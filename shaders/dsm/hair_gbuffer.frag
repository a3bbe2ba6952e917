#version 460
// Hair in the G-buffer: the strand's colour as albedo and its tangent in place of a normal, marked
// SHADING_HAIR in w so that lighting shades it with Kajiya-Kay (dsm/kajiya_kay.glsl).
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(location = 0) in vec3 inTangent;
layout(location = 1) in vec3 inColor;

layout(location = 0) out vec4 outAlbedo;
layout(location = 1) out vec4 outNormal;

void main() {
    outAlbedo = vec4(inColor, 1.0);
    outNormal = vec4(normalize(inTangent), SHADING_HAIR);
}
