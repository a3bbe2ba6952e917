#version 460
// Hair ribbons by vertex pulling, drawn as one triangle strip without vertex or index buffers:
// vertices 2i and 2i+1 are the two edges of ribbon point i (dsm/ribbon.glsl). Each strand is
// bracketed by zero-width copies of its end points, so the strip's joins between strands are
// zero-area triangles.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "dsm/dsm_common.glsl"

layout(push_constant) uniform Push { RibbonDrawPush draw; };
#include "dsm/ribbon.glsl"

layout(location = 0) out vec3 outTangent;
layout(location = 1) out vec3 outColor;
layout(location = 2) out float outAlpha;  // opacity x coverage
layout(location = 3) out float outDepth;  // dsmDepth from the viewer
layout(location = 4) out vec3 outWorld;
// Flat: the provoking vertex of strip triangle k is vertex k, whose point k / 2 is the first of the
// segment the triangle belongs to (dsm/oit_hair.frag).
layout(location = 5) flat out uint outSegment;

void main() {
    GpuHairPoint point = points[gl_VertexIndex >> 1];
    RibbonSection s = ribbonSection(point);
    vec3 p = point.position;
    vec3 world = p + s.side * (((gl_VertexIndex & 1) != 0 ? 0.5 : -0.5) * s.drawn);
    gl_Position = views.viewProj[draw.viewRow] * vec4(world, 1.0);
    outTangent = point.tangent;
    outColor = strands[point.strand].color;
    outAlpha = s.alpha;
    outDepth = dsmDepth(draw.view.viewer, draw.view.viewerIsPoint, p);
    outWorld = world;
    outSegment = uint(gl_VertexIndex >> 1);
}
