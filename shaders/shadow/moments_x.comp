#version 460
// Moment shadow maps, pass 1 of 2: depth -> moments (VSM, EVSM or MSM, per the layer's light),
// blurred along x. Computed from the depth map here, in compute, so that the raster pass stays
// depth-only. One z slice of the dispatch per shadow layer; layers without moments return at once.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "shadow/moments.glsl"
#include "shadow/blur.glsl"

layout(local_size_x = BLUR_GROUP, local_size_y = BLUR_LANES) in;
#include "shadow/bindings.h"
layout(set = 0, binding = MOMENT_ROWS_DEPTH_MAP) uniform sampler2DArray shadowDepth;  // nearest
layout(set = 0, binding = MOMENT_ROWS_OUT, rgba32f) uniform writeonly image2DArray rowMoments;
layout(set = 0, binding = MOMENT_ROWS_LAYERS, std430) readonly buffer Layers { GpuShadowLayer shadowLayers[]; };
layout(set = 0, binding = MOMENT_ROWS_PARAMS) uniform Params { GpuShadowParams params; };

void main() {
    uint layerIndex = gl_WorkGroupID.z;
    GpuShadowLayer layer = shadowLayers[layerIndex];
    if (layer.momentLayer == SHADOW_NO_MOMENTS) return;  // the same for the whole group
    int res = int(params.resolution);
    int radius = min(int(params.blurRadius), BLUR_MAX_RADIUS);
    uint lane = gl_LocalInvocationID.y;
    int y = min(int(gl_GlobalInvocationID.y), res - 1);
    int start = int(gl_WorkGroupID.x) * BLUR_GROUP - radius;
    for (int i = int(gl_LocalInvocationID.x); i < BLUR_GROUP + 2 * radius; i += BLUR_GROUP) {
        int x = clamp(start + i, 0, res - 1);
        float depth = texelFetch(shadowDepth, ivec3(x, y, layerIndex), 0).r;
        blurTile[lane][i] = encodeMoments(layer.momentFilter, linearShadowDepth(layer, depth), params.moments);
    }
    barrier();
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, ivec2(res)))) return;
    imageStore(rowMoments, ivec3(texel, layer.momentLayer), blurTaps(lane, int(gl_LocalInvocationID.x), radius));
}
