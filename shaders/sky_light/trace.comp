#version 460
// Sky visibility: a few cosine-distributed rays per traced receiver (one camera pixel of each
// step x step block) through the occupancy volume (voxel/occupancy.glsl). What a texel keeps is
// which rays are clear, as a bit mask, beside the receiver's depth: weigh.comp turns the mask into
// the share of the sky's radiance, so a change of the sky alone (a moving sun) re-weighs the rays
// without tracing them again. With a phase (geometry moving under a still view) a texel is traced
// when it is its turn or when its receiver is not the one its mask was traced for.
// The rays of texels SKY_TILE apart share a rotation; a SKY_TILE^2 block holds them all. A
// single-sided triangle blocks a ray only where its front faces the sky (the voxels' facing bits,
// src/voxel/occupancy_volume.h): a sky dome whose fronts face inward lets the sky in.
#extension GL_GOOGLE_include_directive : require
#include "sky_light/types.h"
#include "core/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = SKY_TRACE_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = SKY_TRACE_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = SKY_TRACE_GBUFFER_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = SKY_TRACE_OUT, rg32ui) uniform uimage2D outClearRays;
layout(push_constant) uniform Push { SkyLightPush pc; };
#define OCCUPANCY_BINDING SKY_TRACE_OCCUPANCY
#include "voxel/occupancy.glsl"
#include "sky_light/surface.glsl"
#include "sky_light/rays.glsl"

void main() {
    const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, imageSize(outClearRays)))) return;
    const ivec2 pixel = min(tracedPixel(texel, pc.traceStep), ivec2(frame.width, frame.height) - 1);
    const uint depthBits = floatBitsToUint(texelFetch(gDepth, pixel, 0).r);
    if (pc.tracePhase != SKY_TRACE_EVERY_TEXEL && uint((texel.x & 1) + 2 * (texel.y & 1)) != pc.tracePhase &&
        imageLoad(outClearRays, texel).g == depthBits)
        return;
    const SkyReceiver r = skyReceiver(pixel);
    if (!r.surface || pc.rays == 0u || occupancy.grid.dims.x == 0u) {
        imageStore(outClearRays, texel, uvec4(0xFFFFFFFFu, depthBits, 0u, 0u));
        return;
    }
    const float voxel = occupancyVoxelSize();
    const vec3 start = r.p + r.n * (pc.startOffset * voxel);
    const float reach = length(vec3(occupancy.grid.dims)) * voxel;  // leaves the grid from anywhere in it
    const float rank = tileRank(texel);
    uint clear = 0u;
    for (uint k = 0u; k < pc.rays; ++k) {
        const vec3 d = rayDirection(r.n, k, pc.rays, rank);
        // Rays below the horizon meet the black half of the sky whatever they cross: not traced.
        if (d.y > 0.0 && skySegmentClear(start, start + d * reach, 0.5)) clear |= 1u << k;
    }
    imageStore(outClearRays, texel, uvec4(clear, depthBits, 0u, 0u));
}
