#version 460
// Auto exposure, step 1: the histogram of log2(1e-6 + luminance) over the geometry pixels (alpha 1
// in "hdr"; the sky has alpha 0). Each workgroup bins its tile in shared memory, then adds its
// non-empty bins into the frame's histogram (which exposure_resolve.comp leaves zeroed).
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "lighting/lighting_bindings.h"

layout(local_size_x = 16, local_size_y = 16) in;
layout(set = 0, binding = EXPOSURE_HDR, rgba32f) uniform readonly image2D hdrImage;
// Per bin: (pixel count, low and high word of the sum of in-bin positions, unused).
layout(set = 0, binding = EXPOSURE_HISTOGRAM, std430) buffer Histogram { uvec4 bins[EXPOSURE_BINS]; };

shared uint tileCounts[EXPOSURE_BINS];
shared uint tilePositions[EXPOSURE_BINS];  // at most 1024 x 65535: fits 32 bits

const float kBinsPerEv = float(EXPOSURE_BINS) / (EXPOSURE_MAX_EV - EXPOSURE_MIN_EV);

void meter(ivec2 pixel) {
    if (any(greaterThanEqual(pixel, imageSize(hdrImage)))) return;
    vec4 c = imageLoad(hdrImage, pixel);
    if (!(c.a > 0.5)) return;
    float ev = log2(1e-6 + dot(max(c.rgb, vec3(0.0)), vec3(0.2126, 0.7152, 0.0722)));
    // A NaN fails every comparison and counts as black; anything brighter than the range, as its top.
    float x = ev >= EXPOSURE_MIN_EV ? min((ev - EXPOSURE_MIN_EV) * kBinsPerEv, float(EXPOSURE_BINS) - 1e-3) : 0.0;
    uint bin = uint(x);
    uint position = min(uint((x - float(bin)) * EXPOSURE_BIN_STEPS), uint(EXPOSURE_BIN_STEPS) - 1u);
    atomicAdd(tileCounts[bin], 1u);
    atomicAdd(tilePositions[bin], position);
}

void main() {
    uint i = gl_LocalInvocationIndex;
    for (uint b = i; b < EXPOSURE_BINS; b += 256u) tileCounts[b] = 0u, tilePositions[b] = 0u;
    barrier();
    ivec2 origin = ivec2(gl_WorkGroupID.xy) * EXPOSURE_TILE + ivec2(gl_LocalInvocationID.xy);
    for (int y = 0; y < EXPOSURE_TILE; y += 16)
        for (int x = 0; x < EXPOSURE_TILE; x += 16) meter(origin + ivec2(x, y));
    barrier();
    for (uint b = i; b < EXPOSURE_BINS; b += 256u) {
        uint count = tileCounts[b];
        if (count == 0u) continue;
        atomicAdd(bins[b].x, count);
        uint add = tilePositions[b];
        uint before = atomicAdd(bins[b].y, add);
        if (before + add < before) atomicAdd(bins[b].z, 1u);  // the low word wrapped: carry
    }
}
