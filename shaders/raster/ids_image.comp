#version 460
// raster/ids.comp with depth stored into the R32_SFLOAT shadow map itself (src/raster).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#define RASTER_DEPTH_IMAGE
#include "shared/types.h"
#include "raster/ids.glsl"
