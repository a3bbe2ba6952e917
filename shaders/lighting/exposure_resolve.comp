#version 460
// Auto exposure, step 2 (one workgroup, an invocation a bin): the mean log luminance of the geometry
// pixels ranked between the low and the high percentile of the histogram (Filament's and other
// engines' metering: the darkest and the brightest pixels do not move the exposure). A bin the window
// cuts counts with the share of its pixels inside, each at the bin's mean. The exposure that maps
// that mean to middle grey 0.18 is approached exponentially (Filament's adaptation, in log space)
// from the previous frames'. A frame without geometry keeps the last exposure. The histogram is
// zeroed for the next frame.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "lighting/lighting_bindings.h"

layout(local_size_x = EXPOSURE_BINS) in;
layout(set = 0, binding = EXPOSURE_HISTOGRAM, std430) buffer Histogram { uvec4 bins[EXPOSURE_BINS]; };
layout(set = 0, binding = EXPOSURE_STATE, std430) buffer State { AutoExposureState state; };
layout(push_constant) uniform Push { AutoExposurePush pc; };

shared uint ranks[EXPOSURE_BINS];  // inclusive prefix sum of the counts
shared vec2 sums[EXPOSURE_BINS];   // (weight, weight x mean EV) inside the window

const float kEvPerBin = (EXPOSURE_MAX_EV - EXPOSURE_MIN_EV) / float(EXPOSURE_BINS);

void main() {
    uint i = gl_LocalInvocationIndex;
    uvec4 bin = bins[i];
    ranks[i] = bin.x;
    barrier();
    for (uint s = 1u; s < EXPOSURE_BINS; s <<= 1u) {
        uint below = i >= s ? ranks[i - s] : 0u;
        barrier();
        ranks[i] += below;
        barrier();
    }
    float total = float(ranks[EXPOSURE_BINS - 1u]);
    float first = float(ranks[i] - bin.x), last = float(ranks[i]);
    float weight = max(0.0, min(last, pc.highFraction * total) - max(first, pc.lowFraction * total));
    float position = bin.x == 0u ? 0.0 : (float(bin.z) * 4294967296.0 + float(bin.y)) / float(bin.x);
    float meanEv = EXPOSURE_MIN_EV + (float(i) + (position + 0.5) / EXPOSURE_BIN_STEPS) * kEvPerBin;
    sums[i] = vec2(weight, weight * meanEv);
    bins[i] = uvec4(0u);
    barrier();
    for (uint s = EXPOSURE_BINS / 2u; s > 0u; s >>= 1u) {
        if (i < s) sums[i] += sums[i + s];
        barrier();
    }
    if (i != 0u) return;
    if (total < 0.5) {
        if (state.valid == 0u) state.exposure = 1.0;
        return;
    }
    float logAverage = sums[0].y / sums[0].x * log(2.0);  // natural log, as eval's autoExposure
    float target = log(0.18) - logAverage;
    float rate = state.valid == 0u ? 1.0 : pc.rate;
    state.adaptedLog = mix(state.valid == 0u ? target : state.adaptedLog, target, rate);
    state.exposure = exp(state.adaptedLog);
    state.logAverage = logAverage;
    state.valid = 1u;
}
