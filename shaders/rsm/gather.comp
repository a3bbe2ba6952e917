#version 460
// The RSM gather (rsm/gather.glsl) without voxel visibility.
#extension GL_GOOGLE_include_directive : require
#include "rsm/gather.glsl"
