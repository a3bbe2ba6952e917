#version 460
// raster/tiles.glsl straight into an R32_SFLOAT shadow map and its ID layers.
#extension GL_GOOGLE_include_directive : require
#define RASTER_TARGET_IMAGE
#include "shared/types.h"
#include "raster/raster.glsl"
#include "raster/tiles.glsl"
