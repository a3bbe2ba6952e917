#version 460
// Visibility ID of the draw's triangle (render/visibility.glsl): camera visibility buffer and the
// shadow layers that feed an RSM. Opaque casters: no discard, so early depth testing stays on.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(push_constant) uniform Push { DrawPush draw; };  // ShadowDrawPush keeps these offsets
layout(location = 0) out uint outId;

void main() { outId = draw.triangleBase + uint(gl_PrimitiveID) + 1u; }
