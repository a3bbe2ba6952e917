// Forwards to core/lights.glsl, where the file lives now, for includers that still name this path.
#include "core/lights.glsl"
