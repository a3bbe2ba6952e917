#version 460
// Geometry injection from the camera's G-buffer (Kaplanyan & Dachsbacher 2010): occluders the
// light does not see still block propagated light. One surfel per step x step pixel block; its area
// is the block's world footprint over the viewing cosine. Summed in fixed point with the RSM's
// surfels (lpv/fixed_point.glsl, lpv/inject.comp).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "shared/types.h"
#include "lpv/bindings.h"
#include "core/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = LPV_CAMERA_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = LPV_CAMERA_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = LPV_CAMERA_GBUFFER_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = LPV_CAMERA_GEOMETRY_SUMS, std430) buffer GeometrySums { int64_t geometrySums[]; };
layout(push_constant) uniform Push { LpvPush pc; };

#include "lpv/sh.glsl"
#include "lpv/volume.glsl"
#include "lpv/fixed_point.glsl"
#include "lpv/subgroup_cells.glsl"
#include "lpv/fixed_point_add.glsl"

void main() {
    int step = int(pc.cameraGeometryStep);
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy) * step + step / 2;
    if (any(greaterThanEqual(pixel, ivec2(frame.width, frame.height)))) return;
    float depth = texelFetch(gDepth, pixel, 0).r;
    if (depth >= 1.0) return;
    vec3 x = pixelWorldPosition(frame, pixel, depth);
    vec3 toEye = frame.eye - x;
    float dist = length(toEye);
    vec4 g = texelFetch(gNormal, pixel, 0);
    // Hair (SHADING_HAIR, --translucency off) is no surface: a strand blocks in proportion to its
    // coverage of a cell, not with a facing side, and its normal target holds a tangent.
    if (g.w > 1.5) return;
    vec3 n = normalize(g.xyz);
    if (dot(n, toEye) < 0.0) n = -n;
    float side = dist * frame.pixelSpread * float(step);
    float area = side * side / max(dot(n, toEye / dist), 0.2);
    vec4 lobe = cosineLobe(n) / LOBE_PEAK;
    for (uint k = 0; k < pc.cascadeCount; ++k) {
        float cell = pc.cascades[k].origin.w;
        ivec3 g = ivec3(floor(gridCoord(k, x) + 0.5));
        if (!insideGrid(g)) continue;
        const i64vec4 q = toFixed(lobe * min(area / (cell * cell), 1.0), LPV_GEOMETRY_FRACTION_BITS);
        uint base = geometryIndex(k, g) * 4u;
        ADD_FIXED(geometrySums, base, q)
    }
}
