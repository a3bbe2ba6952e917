#version 460
// The injection's fixed-point sums (lpv/fixed_point.glsl) to the float volumes the propagation
// reads: per cascade and cell, the light of each colour (at its cell's scale) into light volume A and
// the blocking into the geometry volume.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#include "shared/types.h"
#include "lpv/bindings.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(set = 0, binding = LPV_RESOLVE_LIGHT_SUMS, std430) readonly buffer LightSums { i64vec4 lightSums[]; };
layout(set = 0, binding = LPV_RESOLVE_GEOMETRY_SUMS, std430) readonly buffer GeometrySums { i64vec4 geometrySums[]; };
layout(set = 0, binding = LPV_RESOLVE_RANGES, std430) readonly buffer Ranges { uint ranges[]; };
layout(set = 0, binding = LPV_RESOLVE_LIGHT, std430) writeonly buffer Light { vec4 light[]; };
layout(set = 0, binding = LPV_RESOLVE_GEOMETRY, std430) writeonly buffer Geometry { vec4 geometry[]; };
layout(push_constant) uniform Push { LpvPush pc; };

#include "lpv/volume.glsl"
#include "lpv/fixed_point.glsl"

void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID.x, gl_GlobalInvocationID.y, gl_GlobalInvocationID.z % pc.resolution);
    uint cascade = gl_GlobalInvocationID.z / pc.resolution;
    if (any(greaterThanEqual(cell, ivec3(pc.resolution))) || cascade >= pc.cascadeCount) return;
    const int fractionBits = lightFractionBits(pc.vplCount);
    for (uint ch = 0; ch < 3u; ++ch) {
        const uint i = lightIndex(cascade, ch, cell);
        light[i] = fromFixed(lightSums[i], fractionBits - lightExponent(ranges[lightRangeIndex(cascade, ch, cell)]));
    }
    const uint g = geometryIndex(cascade, cell);
    geometry[g] = fromFixed(geometrySums[g], LPV_GEOMETRY_FRACTION_BITS);
}
