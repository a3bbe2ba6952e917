// Forwards to core/reconstruct.glsl, where the file lives now, for includers that still name this path.
#include "core/reconstruct.glsl"
