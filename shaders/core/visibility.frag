#version 460
// Visibility ID of the draw's triangle (core/visibility.glsl): camera visibility buffer and the
// shadow layers that feed an RSM. Opaque casters: no discard, so early depth testing stays on.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(location = 3) flat in uint inIdBase;  // from the vertex stage (core/visibility.glsl)
layout(location = 0) out uint outId;

void main() { outId = inIdBase + uint(gl_PrimitiveID) + 1u; }
