#version 460
// The RSM gather (rsm/gather.glsl) with the pattern's radii shifted per receiver (--rsm-radii
// shifted): a pipeline of its own, as placing and weighing each sample in the shader costs the
// default gather 0.1-0.2 ms at 1080p on the H100.
#extension GL_GOOGLE_include_directive : require
#define RSM_SHIFTED_RADII
#include "rsm/gather.glsl"
