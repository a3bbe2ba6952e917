// Binding numbers of the occupancy volume's passes (set 0), included by their GLSL and by
// src/voxel/occupancy_volume.cpp: each number is written here only. The voxelize pass also binds
// the scene's instances and drawn triangles (core/scene_bindings.h).
#ifndef PENUMBRA_VOXEL_BINDINGS_H
#define PENUMBRA_VOXEL_BINDINGS_H

// voxel/voxelize.comp.
#define VOXELIZE_MATERIALS 1
#define VOXELIZE_OCCUPANCY 2
#define VOXELIZE_CHUNKS 3

// voxel/bricks.comp.
#define BRICKS_OCCUPANCY 0

#endif
