#version 460
// The RSM gather (rsm/gather.glsl) as it runs by default: the far half of the samples drawn by flux
// (--rsm-far flux), the disc's radii shifted per receiver (--rsm-radii shifted), both compiled in.
#extension GL_GOOGLE_include_directive : require
#define RSM_FAR_FLUX
#define RSM_SHIFTED_RADII
#include "rsm/gather.glsl"
