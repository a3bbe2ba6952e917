#version 460
// Hair ribbons by vertex pulling, drawn as one triangle strip without vertex or index buffers:
// vertices 2i and 2i+1 are the two edges of ribbon point i. Each strand is bracketed by zero-width
// copies of its end points, so the strip's joins between strands are zero-area triangles.
// The ribbon faces the viewer (a camera or light position, or a directional light) and is never
// narrower than `footprint.w` pixels/texels, so that it neither vanishes nor breaks up; a thinner
// strand passes its true coverage on as alpha (what it casts into a deep shadow map).
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "dsm/dsm_common.glsl"

layout(set = 0, binding = 0, std430) readonly buffer Views { mat4 viewProj[]; } views;
layout(set = 0, binding = 3, std430) readonly buffer Points { GpuHairPoint points[]; };
layout(set = 0, binding = 4, std430) readonly buffer Strands { vec4 strands[]; };  // rgb colour, a opacity
layout(push_constant) uniform Push { HairDrawPush draw; };

layout(location = 0) out vec3 outTangent;
layout(location = 1) out vec3 outColor;
layout(location = 2) out float outAlpha;  // opacity x coverage
layout(location = 3) out float outDepth;  // dsmDepth from the viewer
layout(location = 4) out vec3 outWorld;

void main() {
    GpuHairPoint point = points[gl_VertexIndex >> 1];
    vec3 p = point.position.xyz, t = point.tangent.xyz;
    vec4 strand = strands[uint(point.tangent.w)];
    vec3 toViewer = draw.viewer.w > 0.5 ? draw.viewer.xyz - p : draw.viewer.xyz;
    float dist = length(toViewer);
    vec3 side = cross(t, toViewer);
    float len = length(side);
    // Seen end-on the ribbon has no facing side: any direction across the strand will do.
    side = len > 1e-6 * dist ? side / len : normalize(cross(t, abs(t.x) < 0.9 ? vec3(1, 0, 0) : vec3(0, 1, 0)));
    float pixel = draw.footprint.x * (draw.footprint.y > 0.5 ? dist : 1.0);
    float width = point.position.w;
    float drawn = width > 0.0 ? max(width, pixel * draw.footprint.w) : 0.0;
    vec3 world = p + side * (((gl_VertexIndex & 1) != 0 ? 0.5 : -0.5) * drawn);
    gl_Position = views.viewProj[draw.ids.x] * vec4(world, 1.0);
    outTangent = t;
    outColor = strand.rgb;
    outAlpha = drawn > 0.0 ? strand.a * width / drawn : 0.0;
    outDepth = dsmDepth(draw.viewer, p);
    outWorld = world;
}
