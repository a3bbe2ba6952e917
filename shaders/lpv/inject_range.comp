#version 460
// The scale of the light injection's fixed-point sums (lpv/fixed_point.glsl): per cascade, colour
// and cell, the largest |coefficient| any VPL adds there, kept as float bits (for non-negative floats
// atomicMax on the bits orders them as the floats, and a maximum is the same in any order).
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "shared/types.h"
#include "lpv/bindings.h"

layout(local_size_x = 64) in;
layout(set = 0, binding = LPV_RANGE_VPLS, std430) readonly buffer Vpls { GpuVpl vpls[]; };
layout(set = 0, binding = LPV_RANGE_RANGES, std430) buffer Ranges { uint ranges[]; };
layout(push_constant) uniform Push { LpvPush pc; };

#include "lpv/sh.glsl"
#include "lpv/volume.glsl"
#include "lpv/vpl_light.glsl"
#include "lpv/subgroup_cells.glsl"

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pc.vplCount) return;
    GpuVpl v = vpls[i];
    if (v.exists == 0u) return;
    vec3 largest;
    for (uint ch = 0; ch < 3u; ++ch) largest[ch] = largestMagnitude(vplLight(v, ch));
    const uint colourStride = cellsPerVolume();
    for (uint k = 0; k < pc.cascadeCount; ++k) {
        const Splat splat = vplSplat(v, k);
        for (uint corner = 0; corner < 8u; ++corner) {
            const ivec3 c = splatCell(splat, corner);
            const float w = splatWeight(splat, corner);
            if (!insideGrid(c) || w == 0.0) continue;
            // Rounding is monotonic: no coefficient times w rounds above the largest times w.
            const uvec3 bits = floatBitsToUint(largest * w);
            const uint key = lightRangeIndex(k, 0u, c);
            LPV_BY_CELL(key,
                        const uvec3 largest_ = subgroupMax(bits);
                        if (subgroupElect()) for (uint ch = 0u; ch < 3u; ++ch)
                            atomicMax(ranges[cell_ + ch * colourStride], largest_[ch]);,
                        for (uint ch = 0u; ch < 3u; ++ch) atomicMax(ranges[key + ch * colourStride], bits[ch]);)
        }
    }
}
