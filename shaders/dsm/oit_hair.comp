#version 460
// Camera translucency build for hair in compute (--raster compute|auto; dsm/ribbon_raster.glsl says
// why): every segment's ribbon in the camera's view, each pixel it covers in front of the opaque
// surface pushing a node (dsm/oit_insert.glsl) with the strand's coverage as alpha.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#include "shared/types.h"
#include "dsm/dsm_common.glsl"

layout(local_size_x = 64) in;
layout(push_constant) uniform Push { OitBuildPush draw; };

#include "dsm/ribbon.glsl"
#include "dsm/oit_insert.glsl"
#include "dsm/ribbon_raster.glsl"

void ribbonFragment(ivec2 pixel, float ndcDepth, float viewerDepth, float alpha, vec3 world, vec3 tangent,
                    vec3 colour, uint segment) {
    oitInsert(pixel, ndcDepth, colour, alpha, tangent, segment);
}

void main() {
    uint i;
    if (ribbonSegmentIndex(i)) rasterRibbonSegment(i, vec2(textureSize(opaqueDepth, 0)));
}
