#version 460
// raster/ids.comp for a 2D ID image (the camera's visibility buffer, src/render/gbuffer_pass.cpp).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#define RASTER_ID_IMAGE_2D
#include "shared/types.h"
#include "raster/ids.glsl"
