#version 460
// Sky visibility per pixel: a few cosine-distributed rays from the receiver through the occupancy
// volume (voxel/occupancy.glsl). What a pixel keeps is the share of the sky's radiance, per colour
// channel, that its clear rays see: the filter multiplies it by the unoccluded irradiance, so a
// receiver that sees only the horizon takes the horizon's colour and an open one is exact.
// The rays of pixels SKY_TILE apart share a rotation; a SKY_TILE^2 block holds them all.
#extension GL_GOOGLE_include_directive : require
#include "sky_light/types.h"
#include "core/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = SKY_TRACE_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = SKY_TRACE_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = SKY_TRACE_GBUFFER_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = SKY_TRACE_OUT, rgba16f) uniform writeonly image2D outVisibility;
layout(push_constant) uniform Push { SkyLightPush pc; };
#define OCCUPANCY_BINDING SKY_TRACE_OCCUPANCY
#include "voxel/occupancy.glsl"
#include "sky_light/sky_sh.glsl"
#include "sky_light/surface.glsl"

// The 4x4 Bayer matrix's rank of a pixel within its tile: neighbours take distant rotations.
float tileRank(ivec2 pixel) {
    const uint bayer[16] = uint[16](0u, 8u, 2u, 10u, 12u, 4u, 14u, 6u, 3u, 11u, 1u, 9u, 15u, 7u, 13u, 5u);
    const ivec2 t = pixel & (SKY_TILE - 1);
    return (float(bayer[t.y * SKY_TILE + t.x]) + 0.5) / float(SKY_TILE * SKY_TILE);
}

// Ray k of `count` about n: cosine-distributed, stratified in the polar angle, the golden angle apart
// in azimuth, the whole set turned by `rank` of a turn.
vec3 rayDirection(vec3 n, uint k, uint count, float rank) {
    const float u = (float(k) + rank) / float(count);
    const float phi = 6.28318530718 * (float(k) * 0.618034 + rank);
    const float r = sqrt(u);
    const vec3 t = normalize(abs(n.y) < 0.9 ? cross(n, vec3(0.0, 1.0, 0.0)) : cross(n, vec3(1.0, 0.0, 0.0)));
    const vec3 b = cross(n, t);
    return normalize(t * (r * cos(phi)) + b * (r * sin(phi)) + n * sqrt(max(1.0 - u, 0.0)));
}

void main() {
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(frame.width, frame.height)))) return;
    const SkyReceiver r = skyReceiver(pixel);
    if (!r.surface || pc.rays == 0u || occupancy.grid.dims.x == 0u) {
        imageStore(outVisibility, pixel, vec4(1.0));
        return;
    }
    const float voxel = occupancyVoxelSize();
    const vec3 start = r.p + r.n * (pc.startOffset * voxel);
    const float reach = length(vec3(occupancy.grid.dims)) * voxel;  // leaves the grid from anywhere in it
    const float rank = tileRank(pixel);
    vec3 seen = vec3(0.0), total = vec3(0.0);
    uint clear = 0u;
    for (uint k = 0u; k < pc.rays; ++k) {
        const vec3 d = rayDirection(r.n, k, pc.rays, rank);
        // Weighted by the sky above the horizon only: the truncated series rings below it, where
        // the ground blocks the rays, and would count that as hidden sky.
        const vec3 l = d.y > 0.0 ? skyRadiance(pc, d) : vec3(0.0);
        const bool open = segmentClear(start, start + d * reach, 0.5);
        total += l;
        if (open) { seen += l; ++clear; }
    }
    // A ray set that sees no radiance at all (a black sky's side) counts its clear rays instead.
    const vec3 share = mix(seen / max(total, vec3(1e-20)), vec3(float(clear) / float(pc.rays)),
                           vec3(lessThanEqual(total, vec3(0.0))));
    imageStore(outVisibility, pixel, vec4(share, 1.0));
}
