#version 460
// Light and geometry injection of the down-sampled VPLs. Light: a VPL of flux phi is a Lambertian
// emitter of intensity phi / pi * max(0, n.w), i.e. SH coefficients phi / pi * CosineLobe(n), added
// to the cell of x + 0.5 cell * n (half a cell along the normal, against self-illumination). The
// RSM flux already contains the texel's footprint (rsm/rsm.frag), so no surfel-area guess is needed.
// Geometry: the surfel blocks area / cell^2 of the cell's cross-section, as a cosine lobe around its
// normal scaled to peak at that coverage, added at the nearest geometry-volume corner.
// Every cascade that holds the VPL receives it: cascades propagate independently. In the coarser
// cascades most VPLs of a subgroup (neighbouring RSM texels) land in the same cell: they are summed
// in the subgroup first, one atomic per coefficient instead of one per VPL (on the H100 the room's
// injection into 3 cascades took 5 ms with per-VPL atomics).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_atomic_float : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "shared/types.h"
#include "lpv/bindings.h"

layout(local_size_x = 64) in;
layout(set = 0, binding = LPV_INJECT_VPLS, std430) readonly buffer Vpls { GpuVpl vpls[]; };
layout(set = 0, binding = LPV_INJECT_LIGHT, std430) buffer LightVolume { float lightCoeffs[]; };
layout(set = 0, binding = LPV_INJECT_GEOMETRY, std430) buffer GeometryVolume { float geometryCoeffs[]; };
layout(push_constant) uniform Push { LpvPush pc; };

#include "lpv/sh.glsl"
#include "lpv/volume.glsl"
#include "lpv/subgroup_add.glsl"

const float PI = 3.14159265358979;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pc.vplCount) return;
    GpuVpl v = vpls[i];
    if (v.position.w < 0.5) return;
    vec3 n = v.normal.xyz;
    vec4 lobe = cosineLobe(n);
    for (uint k = 0; k < pc.cascadeCount; ++k) {
        float cell = pc.cascades[k].origin.w;
        ivec3 c = ivec3(floor(gridCoord(k, v.position.xyz + 0.5 * cell * n)));
        if (insideGrid(c)) {
            for (uint ch = 0; ch < 3u; ++ch) {
                vec4 coeffs = lobe * (v.flux[ch] / PI);
                uint base = lightIndex(k, ch, c) * 4u;
                ADD_COEFFS(lightCoeffs, base, coeffs)
            }
        }
        ivec3 g = ivec3(floor(gridCoord(k, v.position.xyz) + 0.5));  // nearest cell corner
        if (insideGrid(g) && pc.voxelFaces == 0u) {  // the occupancy volume's faces block instead (--lpv-geometry voxels)
            vec4 blocking = lobe * (min(v.normal.w / (cell * cell), 1.0) / LOBE_PEAK);
            uint base = geometryIndex(k, g) * 4u;
            ADD_COEFFS(geometryCoeffs, base, blocking)
        }
    }
}
