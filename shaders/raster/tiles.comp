#version 460
// raster/tiles.glsl into the depth buffers (targets the compute rasterizer cannot write: D32_SFLOAT).
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "raster/raster.glsl"
#include "raster/tiles.glsl"
