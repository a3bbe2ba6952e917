#version 460
// DSM build for hair in compute (--raster compute|auto; dsm/ribbon_raster.glsl says why): every
// segment's ribbon in one DSM layer's view, each texel it covers pushing a node (dsm/dsm_insert.glsl).
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "dsm/dsm_common.glsl"

layout(local_size_x = 64) in;
layout(push_constant) uniform Push { DsmBuildPush draw; };

#include "dsm/ribbon.glsl"
#include "dsm/dsm_insert.glsl"
#include "dsm/ribbon_raster.glsl"

void ribbonFragment(ivec2 pixel, float ndcDepth, float viewerDepth, float alpha, vec3 world, vec3 tangent,
                    vec3 colour, uint segment) {
    dsmInsert(uvec2(pixel), viewerDepth, alpha, world);
}

void main() {
    uint i;
    if (ribbonSegmentIndex(i)) rasterRibbonSegment(i, vec2(float(draw.resolution)));
}
