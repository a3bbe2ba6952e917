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

#include "lpv/camera_surfel.glsl"

void main() {
    const CameraSurfel s = cameraSurfel(gl_GlobalInvocationID.xy, int(pc.cameraGeometryStep));
    if (!s.valid) return;
    vec4 lobe = cosineLobe(s.n) / LOBE_PEAK;
    for (uint k = 0; k < pc.cascadeCount; ++k) {
        float cell = pc.cascades[k].cellSize;
        ivec3 g = ivec3(floor(gridCoord(k, s.x) + 0.5));
        if (!insideGrid(g)) continue;
        const i64vec4 q = toFixed(lobe * min(s.area / (cell * cell), 1.0), LPV_GEOMETRY_FRACTION_BITS);
        uint base = geometryIndex(k, g) * 4u;
        ADD_FIXED(geometrySums, base, q)
    }
}
