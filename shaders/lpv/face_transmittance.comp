#version 460
// LPV occlusion from the occupancy volume (--lpv-geometry voxels; src/voxel/occupancy_volume.h): for
// every cell and axis, the share of the light going from the neighbour below along the axis into the
// cell that no surface stops: LPV_FACE_COLUMNS^2 segments parallel to the axis, from the
// neighbour's centre to this cell's, spread evenly over the shared face, each walked voxel by voxel
// (an axis-aligned walk: the voxels are the segment's). Output per cell a vec4: x, y, z the faces
// towards the -x, -y and -z neighbours. The geometry volume's L1 lobe of a wall blocks a third of the
// light running along it and lets some through it; a wall in the voxels stops what crosses it, and
// leaves a cell's light that runs beside it alone.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "lpv/bindings.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
#define OCCUPANCY_BINDING LPV_FACES_OCCUPANCY
#include "voxel/occupancy.glsl"
layout(set = 0, binding = LPV_FACES_OUT, std430) writeonly buffer Faces { vec4 faces[]; };
layout(push_constant) uniform Push { LpvPush pc; };

#include "lpv/volume.glsl"

// Whether the axis-aligned segment from world point `from` along `axis` for `length` metres meets an
// occupied voxel.
bool columnBlocked(vec3 from, int axis, float length) {
    const vec3 p = (from - occupancy.grid.origin.xyz) / occupancyVoxelSize();
    ivec3 c = ivec3(floor(p));
    const int last = int(floor(p[axis] + length / occupancyVoxelSize()));
    for (; c[axis] <= last; ++c[axis])
        if (voxelOccupied(c)) return true;
    return false;
}

void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID.x, gl_GlobalInvocationID.y, gl_GlobalInvocationID.z % pc.resolution);
    uint cascade = gl_GlobalInvocationID.z / pc.resolution;
    if (any(greaterThanEqual(cell, ivec3(pc.resolution))) || cascade >= pc.cascadeCount) return;
    const float size = pc.cascades[cascade].cellSize;
    const vec3 centre = pc.cascades[cascade].origin + (vec3(cell) + 0.5) * size;
    vec4 open = vec4(1.0);
    for (int axis = 0; axis < 3; ++axis) {
        ivec3 e = ivec3(0);
        e[axis] = 1;
        if (!insideGrid(cell - e)) continue;  // no neighbour below: nothing comes through
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        uint free = 0u;
        for (int i = 0; i < LPV_FACE_COLUMNS * LPV_FACE_COLUMNS; ++i) {
            vec3 start = centre - vec3(e) * size;
            start[u] += ((float(i % LPV_FACE_COLUMNS) + 0.5) / float(LPV_FACE_COLUMNS) - 0.5) * size;
            start[v] += ((float(i / LPV_FACE_COLUMNS) + 0.5) / float(LPV_FACE_COLUMNS) - 0.5) * size;
            free += columnBlocked(start, axis, size) ? 0u : 1u;
        }
        open[axis] = float(free) / float(LPV_FACE_COLUMNS * LPV_FACE_COLUMNS);
    }
    faces[geometryIndex(cascade, cell)] = open;
}
