#version 460
// One propagation step (gather form, Kaplanyan 2009): each cell collects, from each of its 6
// neighbours, the flux the neighbour's intensity sends through the 5 faces of this cell that do not
// touch the neighbour (solid angles 0.4006696846 for the face ahead, 0.4234413544 for each side
// face). Light crossing into the cell is attenuated by the geometry volume sampled on the shared face
// (skipped on the first step, where the light would block itself), or (--lpv-geometry voxels) by the
// share of the face that the occupancy volume leaves open (lpv/face_transmittance.comp), every step. Output: this step's light, and
// the running sum in two halves: near (and every step of cascade 0) and far (the steps of a coarser
// cascade from pc.farFromIteration on, the light that has left the finer cascade's reach; lpv.h).
//
// Unlike the paper, the flux through a face goes on in the direction it travelled (from the
// neighbour's centre to the face) and is re-emitted as the L1 projection of that direction, not as a
// cosine lobe towards the face: the paper's re-emission turns light that moves up through a side face
// into light that moves sideways, which makes propagation diffusive (32^3 x 8 steps: a VPL's light
// reaches about 4 cells; docs/techniques/lpv.md, "Where the light goes").
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "lpv/bindings.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(set = 0, binding = LPV_PROPAGATE_SOURCE, std430) readonly buffer Source { vec4 src[]; };
layout(set = 0, binding = LPV_PROPAGATE_DESTINATION, std430) writeonly buffer Destination { vec4 dst[]; };
layout(set = 0, binding = LPV_PROPAGATE_SUM, std430) buffer Accumulated { vec4 accum[]; };
layout(set = 0, binding = LPV_PROPAGATE_GEOMETRY, std430) readonly buffer GeometryVolume { vec4 geometry[]; };
layout(set = 0, binding = LPV_PROPAGATE_FACES, std430) readonly buffer Faces { vec4 faces[]; };  // --lpv-geometry voxels
layout(push_constant) uniform Push { LpvPush pc; };

#include "lpv/sh.glsl"
#include "lpv/volume.glsl"

const float PI = 3.14159265358979;
const float FRONT_SOLID_ANGLE = 0.4006696846 / PI;
const float SIDE_SOLID_ANGLE = 0.4234413544 / PI;
const ivec3 AXES[6] = ivec3[](ivec3(1, 0, 0), ivec3(-1, 0, 0), ivec3(0, 1, 0), ivec3(0, -1, 0), ivec3(0, 0, 1),
                              ivec3(0, 0, -1));

// Blocking lobe on the face between this cell and the neighbour at -d: bilinear over the face's
// four geometry-volume corners (corner k sits at the light cells' corner k).
vec4 faceGeometry(uint cascade, ivec3 cell, ivec3 d) {
    ivec3 a = cell + max(-d, ivec3(0));  // the corner plane of the shared face
    ivec3 u = d.x != 0 ? ivec3(0, 1, 0) : ivec3(1, 0, 0);
    ivec3 v = d.z != 0 ? ivec3(0, 1, 0) : ivec3(0, 0, 1);
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 4; ++i) {
        ivec3 g = a + u * (i & 1) + v * (i >> 1);
        if (insideGrid(g)) sum += geometry[geometryIndex(cascade, g)];
    }
    return 0.25 * sum;
}

// Direction of travel and solid angle of the 30 faces a cell's light leaves through (5 into each of
// the 6 neighbours): `face` 0 ahead along axis a, 1-4 the side faces.
void faceOf(int a, int face, out vec3 dir, out float solid) {
    dir = vec3(AXES[a]);
    solid = FRONT_SOLID_ANGLE;
    if (face == 0) return;
    ivec3 s1 = AXES[a].x != 0 ? ivec3(0, 1, 0) : ivec3(1, 0, 0);
    ivec3 s2 = ivec3(cross(dir, vec3(s1)));
    vec3 side = vec3(face < 3 ? s1 : s2) * ((face & 1) != 0 ? 1.0 : -1.0);
    dir = (2.0 * dir + side) / sqrt(5.0);
    solid = SIDE_SOLID_ANGLE;
}

// Evaluating an L1 intensity at 30 face directions and clamping the negative lobes at zero sends out
// more flux than the intensity holds (+14% for a cosine lobe). Each cell's light is scaled so that
// what it sends through its 30 faces never exceeds its flux (the integral of I, 4 pi Y0 I.x):
// propagation then never creates light. Scaling as the 6 readers read (constant face directions,
// unrolled) is faster than scaling once as the cell is written: no second pass over the volume.
float outflowScale(vec4 intensity) {
    float sent = 0.0;
    for (int a = 0; a < 6; ++a)
        for (int f = 0; f < 5; ++f) {
            vec3 dir;
            float solid;
            faceOf(a, f, dir, solid);
            sent += solid * max(dot(intensity, shBasis(dir)), 0.0);
        }
    float flux = intensity.x * (4.0 * SH_C0);  // both sides in units of 1/pi (solid angles are / pi)
    return sent > flux ? max(flux, 0.0) / sent : 1.0;
}

void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID.x, gl_GlobalInvocationID.y, gl_GlobalInvocationID.z % pc.resolution);
    uint cascade = gl_GlobalInvocationID.z / pc.resolution;
    if (any(greaterThanEqual(cell, ivec3(pc.resolution))) || cascade >= pc.cascadeCount) return;
    const bool first = pc.iteration == 0u;
    const bool far = cascade > 0u && pc.iteration + 1u >= pc.farFromIteration;
    const bool voxelFaces = pc.occlusion != 0u && pc.voxelFaces != 0u;
    const bool occlusion = pc.occlusion != 0u && !first && !voxelFaces;
    vec4 result[3] = vec4[](vec4(0.0), vec4(0.0), vec4(0.0));
    for (int a = 0; a < 6; ++a) {
        ivec3 d = AXES[a];  // direction of travel: from the neighbour into this cell
        ivec3 from = cell - d;
        if (!insideGrid(from)) continue;
        vec4 blocking = occlusion ? faceGeometry(cascade, cell, d) : vec4(0.0);
        // The face between `from` and this cell is the -axis face of whichever lies higher on the axis.
        const int axis = a / 2;
        const float open = voxelFaces ? faces[geometryIndex(cascade, (a & 1) == 0 ? cell : from)][axis] : 1.0;
        vec4 source[3];
        float scale[3];
        for (uint ch = 0; ch < 3u; ++ch) {
            source[ch] = src[lightIndex(cascade, ch, from)];
            scale[ch] = outflowScale(source[ch]);
        }
        for (int f = 0; f < 5; ++f) {
            vec3 dir;
            float solid;
            faceOf(a, f, dir, solid);
            float transmit = open * (1.0 - clamp(dot(blocking, shBasis(-dir)), 0.0, 1.0));
            // shBasis(dir) * PI: the projection of a beam along dir that integrates, like a cosine
            // lobe, to pi (the solid angles are divided by pi).
            vec4 y = shBasis(dir);
            for (uint ch = 0; ch < 3u; ++ch)
                result[ch] += (solid * transmit * scale[ch] * max(dot(source[ch], y), 0.0) * PI) * y;
        }
    }
    // The first step writes both halves of the sum: until then the buffer held the injection's
    // fixed-point sums (lpv/volume.glsl).
    for (uint ch = 0; ch < 3u; ++ch) {
        uint i = lightIndex(cascade, ch, cell), f = i + 3u * pc.cascadeCount * cellsPerVolume();
        dst[i] = result[ch];
        if (first) {
            accum[i] = src[i] + (far ? vec4(0.0) : result[ch]);
            accum[f] = far ? result[ch] : vec4(0.0);
        } else if (far) {
            accum[f] += result[ch];
        } else {
            accum[i] += result[ch];
        }
    }
}
