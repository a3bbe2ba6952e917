#version 460
// The history weight that the GI technique's measured change asks for, per change texel
// (core/names.h GiChange): over the 5x5 texels around it, the mean of their relative changes (each
// weighed by its luminance), less the part that their spread can explain, over GiAccumulatePush's
// lagTolerance (the technique's). A sampled estimate's gradient also holds the sampling's change (a
// moving light re-samples the RSM), zero on average and different from sample to sample; a change of
// the light's own is alike in all of them. Only a mean beyond kChangeSignificance standard errors counts; 0 where fewer than three
// texels were measured.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "temporal_gi/bindings.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = GI_CHANGE_WEIGHT_CHANGE) uniform sampler2D change;
layout(set = 0, binding = GI_CHANGE_WEIGHT_OUTPUT, r32f) uniform writeonly image2D outWeight;
layout(push_constant) uniform Push { GiAccumulatePush pc; };

const float kChangeSignificance = 2.0;

void main() {
    const ivec2 texel = ivec2(gl_GlobalInvocationID.xy), size = textureSize(change, 0);
    if (any(greaterThanEqual(texel, size))) return;
    vec4 sum = vec4(0.0);  // change, larger luminance, change^2 / larger, samples
    for (int k = 0; k < 25; ++k) {
        const ivec2 t = texel + ivec2(k % 5, k / 5) - 2;
        if (all(greaterThanEqual(t, ivec2(0))) && all(lessThan(t, size))) sum += texelFetch(change, t, 0);
    }
    float weight = 0.0;
    if (sum.w >= 3.0 && sum.y > 0.0) {
        const float mean = sum.x / sum.y, spread = max(sum.z / sum.y - mean * mean, 0.0);
        weight = min(max(abs(mean) - kChangeSignificance * sqrt(spread / (sum.w - 1.0)), 0.0) / pc.lagTolerance, 1.0);
    }
    imageStore(outWeight, texel, vec4(weight, 0.0, 0.0, 0.0));
}
