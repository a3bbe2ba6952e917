#version 460
// Moment shadow maps, pass 2 of 2: the row-blurred moments blurred along y into the filterable
// moment array the filter pass samples (bilinear).
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "shadow/blur.glsl"

layout(local_size_x = BLUR_LANES, local_size_y = BLUR_GROUP) in;
#include "shadow/bindings.h"
layout(set = 0, binding = MOMENT_COLUMNS_ROWS, rgba32f) uniform readonly image2DArray rowMoments;
layout(set = 0, binding = MOMENT_COLUMNS_OUT, rgba32f) uniform writeonly image2DArray moments;
layout(set = 0, binding = MOMENT_COLUMNS_LAYERS, std430) readonly buffer Layers { GpuShadowLayer shadowLayers[]; };
layout(set = 0, binding = MOMENT_COLUMNS_PARAMS) uniform Params { GpuShadowParams params; };

void main() {
    GpuShadowLayer layer = shadowLayers[gl_WorkGroupID.z];
    if (layer.momentLayer == SHADOW_NO_MOMENTS) return;  // the same for the whole group
    int res = int(params.resolution);
    int radius = min(int(params.blurRadius), BLUR_MAX_RADIUS);
    uint lane = gl_LocalInvocationID.x;
    int x = min(int(gl_GlobalInvocationID.x), res - 1);
    int start = int(gl_WorkGroupID.y) * BLUR_GROUP - radius;
    int slice = int(layer.momentLayer);
    for (int i = int(gl_LocalInvocationID.y); i < BLUR_GROUP + 2 * radius; i += BLUR_GROUP)
        blurTile[lane][i] = imageLoad(rowMoments, ivec3(x, clamp(start + i, 0, res - 1), slice));
    barrier();
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, ivec2(res)))) return;
    imageStore(moments, ivec3(texel, slice), blurTaps(lane, int(gl_LocalInvocationID.y), radius));
}
