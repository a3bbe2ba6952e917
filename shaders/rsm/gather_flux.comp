#version 460
// The RSM gather (rsm/gather.glsl) with the far half of the samples drawn by flux (--rsm-far flux,
// the default): a pipeline of its own, so that the disc's pipeline keeps its lean loop.
#extension GL_GOOGLE_include_directive : require
#define RSM_FAR_FLUX
#include "rsm/gather.glsl"
