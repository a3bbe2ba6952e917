#version 460
// Auto exposure, step 2 (one workgroup): the tiles' sums give the log-average luminance; the
// exposure that maps it to middle grey 0.18 is approached exponentially (Filament's adaptation,
// in log space) from the previous frames'. A frame without geometry keeps the last exposure.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "lighting/lighting_bindings.h"

layout(local_size_x = 256) in;
layout(set = 0, binding = EXPOSURE_PARTIALS, std430) readonly buffer Partials { vec2 partials[]; };
layout(set = 0, binding = EXPOSURE_STATE, std430) buffer State { AutoExposureState state; };
layout(push_constant) uniform Push { AutoExposurePush pc; };

shared vec2 sums[256];

void main() {
    uint i = gl_LocalInvocationIndex;
    vec2 v = vec2(0.0);
    for (uint k = i; k < pc.partialCount; k += 256u) v += partials[k];
    sums[i] = v;
    barrier();
    for (uint s = 128u; s > 0u; s >>= 1u) {
        if (i < s) sums[i] += sums[i + s];
        barrier();
    }
    if (i != 0u) return;
    if (sums[0].y < 0.5) {
        if (state.valid == 0u) state.exposure = 1.0;
        return;
    }
    float logAverage = sums[0].x / sums[0].y;
    float target = log(0.18) - logAverage;
    float rate = state.valid == 0u ? 1.0 : pc.rate;
    state.adaptedLog = mix(state.valid == 0u ? target : state.adaptedLog, target, rate);
    state.exposure = exp(state.adaptedLog);
    state.logAverage = logAverage;
    state.valid = 1u;
}
