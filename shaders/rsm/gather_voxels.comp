#version 460
// The RSM gather (rsm/gather.glsl) with voxel visibility (--rsm-visibility voxels; the radii always
// shifted): a pipeline of its own, so that the walk's registers do not lower the default gather's
// occupancy.
#extension GL_GOOGLE_include_directive : require
#define RSM_SHIFTED_RADII
#define RSM_VOXEL_VISIBILITY
#include "rsm/gather.glsl"
