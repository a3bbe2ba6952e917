#version 460
// Light and geometry injection of the down-sampled VPLs. Light: lpv/vpl_light.glsl (a trilinear
// splat half a cell along the normal). The RSM flux
// already contains the texel's footprint (rsm/rsm.frag), so no surfel-area guess is needed.
// Geometry: the surfel blocks area / cell^2 of the cell's cross-section, as a cosine lobe around its
// normal scaled to peak at that coverage, added at the nearest geometry-volume corner.
// Every cascade that holds the VPL receives it: cascades propagate independently. Both are summed in
// fixed point (lpv/fixed_point.glsl: the same sum in any order), the light at the scale
// lpv/inject_range.comp found; lpv/resolve.comp turns the sums into the float volumes. In the coarser
// cascades most VPLs of a subgroup (neighbouring RSM texels) land in the same cell: they are summed
// in the subgroup first, one atomic per coefficient instead of one per VPL (per-VPL atomics on one
// coarse cell serialise).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "shared/types.h"
#include "lpv/bindings.h"

layout(local_size_x = 64) in;
layout(set = 0, binding = LPV_INJECT_VPLS, std430) readonly buffer Vpls { GpuVpl vpls[]; };
layout(set = 0, binding = LPV_INJECT_LIGHT_SUMS, std430) buffer LightSums { int64_t lightSums[]; };
layout(set = 0, binding = LPV_INJECT_GEOMETRY_SUMS, std430) buffer GeometrySums { int64_t geometrySums[]; };
layout(set = 0, binding = LPV_INJECT_RANGES, std430) readonly buffer Ranges { uint ranges[]; };
layout(push_constant) uniform Push { LpvPush pc; };

#include "lpv/sh.glsl"
#include "lpv/volume.glsl"
#include "lpv/vpl_light.glsl"
#include "lpv/fixed_point.glsl"
#include "lpv/subgroup_cells.glsl"
#include "lpv/fixed_point_add.glsl"

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pc.vplCount) return;
    GpuVpl v = vpls[i];
    if (v.exists == 0u) return;
    const int fractionBits = lightFractionBits(pc.vplCount);
    for (uint k = 0; k < pc.cascadeCount; ++k) {
        float cell = pc.cascades[k].cellSize;
        const Splat splat = vplSplat(v, k);
        for (uint corner = 0; corner < 8u; ++corner) {
            const ivec3 c = splatCell(splat, corner);
            const float w = splatWeight(splat, corner);
            if (!insideGrid(c) || w == 0.0) continue;
            for (uint ch = 0; ch < 3u; ++ch) {
                const int e = lightExponent(ranges[lightRangeIndex(k, ch, c)]);
                const i64vec4 q = toFixed(vplLight(v, ch) * w, fractionBits - e);
                uint base = lightIndex(k, ch, c) * 4u;
                ADD_FIXED(lightSums, base, q)
            }
        }
        ivec3 g = ivec3(floor(gridCoord(k, v.position) + 0.5));  // nearest cell corner
        if (insideGrid(g) && pc.voxelFaces == 0u) {  // the occupancy volume's faces block instead (--lpv-geometry voxels)
            vec4 blocking = cosineLobe(v.normal) * (min(v.area / (cell * cell), 1.0) / LOBE_PEAK);
            const i64vec4 q = toFixed(blocking, LPV_GEOMETRY_FRACTION_BITS);
            uint base = geometryIndex(k, g) * 4u;
            ADD_FIXED(geometrySums, base, q)
        }
    }
}
