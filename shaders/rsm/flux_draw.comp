#version 460
// --rsm-far flux, the draws: entry j of a layer inverts the CDF (rsm/flux_sums.comp) at
// (j + jitter_j) / K, the jitter fixed by the seed, so that a receiver taking every (K / m)-th entry
// from an offset of its own draws m stratified samples (rsm/gather.glsl). Each entry keeps its
// texel's packed VPL, so that the gather reads it without first reading where it is.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "rsm/bindings.h"

layout(local_size_x = 256) in;

layout(set = 0, binding = RSM_FLUX_VPLS) uniform usampler2DArray rsmVpls;
layout(set = 0, binding = RSM_FLUX_SUMS, std430) readonly buffer Sums { float sums[]; };
layout(set = 0, binding = RSM_FLUX_DRAWS, std430) writeonly buffer Draws { uint words[]; } draws;  // shared/types.h, 4 words per uvec4
layout(push_constant) uniform Push { RsmFluxPush pc; };

#include "rsm/flux_luminance.glsl"
#include "shared/hash.glsl"

// The first of `count` sums from `first` that exceeds `target` (count - 1 when none does: rounding).
uint firstAbove(uint first, uint count, float target) {
    uint lo = 0u, hi = count - 1u;
    while (lo < hi) {
        const uint mid = (lo + hi) / 2u;
        if (sums[first + mid] > target) hi = mid;
        else lo = mid + 1u;
    }
    return lo;
}

void main() {
    const uint j = gl_GlobalInvocationID.x, layer = gl_WorkGroupID.y, n = pc.curve;
    if (j >= RSM_FLUX_ENTRIES) return;
    const uint runs = pc.layerCount * n * n + layer * n;  // running sums of the runs' totals
    const float total = sums[runs + n - 1u];
    const uint block = layer * RSM_FLUX_BLOCK;
    if (j == 0u) draws.words[4u * block] = floatBitsToUint(total);
    const float jitter = float(hashMix(j ^ hashMix(pc.seed + 0x9e3779b9u)) >> 8) * (1.0 / 16777216.0);
    // Targets are kept below each total: rounding must not carry one past the last lit texel.
    const float below = 1.0 - 1.0 / 1048576.0;
    const float target = min((float(j) + jitter) / float(RSM_FLUX_ENTRIES), below) * total;
    const uint run = firstAbove(runs, n, target), first = (layer * n + run) * n;
    const float before = run > 0u ? sums[runs + run - 1u] : 0.0;
    const uint i = firstAbove(first, n, min(target - before, below * sums[first + n - 1u]));
    const uvec2 t = min(hilbertTexel(n, run * n + i), uvec2(pc.rsmResolution - 1u));
    const uvec4 vpl = texelFetch(rsmVpls, ivec3(t, layer), 0);
    const uint at = 4u * (block + 2u + 2u * j);
    draws.words[at] = vpl.x;
    draws.words[at + 1u] = vpl.y;
    draws.words[at + 2u] = vpl.z;
    draws.words[at + 3u] = vpl.w;
    draws.words[at + 4u] = t.x | (t.y << 16);
}
