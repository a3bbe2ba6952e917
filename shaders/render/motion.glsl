// Forwards to core/motion.glsl, where the file lives now, for includers that still name this path.
#include "core/motion.glsl"
