#version 460
// raster/tiles.glsl straight into the camera's R32_SFLOAT depth and 2D ID image.
#extension GL_GOOGLE_include_directive : require
#define RASTER_TARGET_IMAGE
#define RASTER_ID_IMAGE_2D
#include "shared/types.h"
#include "raster/raster.glsl"
#include "raster/tiles.glsl"
