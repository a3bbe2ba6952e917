#version 460
// The compute rasterizer's layers with visibility IDs (src/raster), after the tile pass: each texel's
// 64-bit depth << 32 | ID splits into the depth buffer (the resolve copies it into the shadow map
// with the other layers) and the ID image (0 where nothing was drawn, core/visibility.glsl).
// One thread per texel, z = row of the layer table (rows without IDs return at once).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#include "shared/types.h"
#include "raster/ids.glsl"

