#version 460
// The RSM gather (rsm/gather.glsl) with the pattern's radii shifted per receiver (--rsm-radii
// shifted): a pipeline of its own, so that the default gather reads precomputed offsets and weights
// instead of placing and weighing each sample in the shader.
#extension GL_GOOGLE_include_directive : require
#define RSM_SHIFTED_RADII
#include "rsm/gather.glsl"
