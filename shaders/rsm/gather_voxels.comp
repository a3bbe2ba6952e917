#version 460
// The RSM gather (rsm/gather.glsl) with voxel visibility (--rsm-visibility voxels): a pipeline of its
// own, so that the walk's registers do not lower the default gather's occupancy (0.26 ms at 1080p on
// the H100).
#extension GL_GOOGLE_include_directive : require
#define RSM_VOXEL_VISIBILITY
#include "rsm/gather.glsl"
