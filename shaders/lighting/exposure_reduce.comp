#version 460
// Auto exposure, step 1: each 16x16 tile's sum of log(1e-6 + luminance) over the geometry pixels
// (alpha 1 in "hdr"; the sky has alpha 0) and their count.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "lighting/lighting_bindings.h"

layout(local_size_x = 16, local_size_y = 16) in;
layout(set = 0, binding = EXPOSURE_HDR, rgba32f) uniform readonly image2D hdrImage;
layout(set = 0, binding = EXPOSURE_PARTIALS, std430) writeonly buffer Partials { vec2 partials[]; };

shared vec2 sums[256];

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    vec2 v = vec2(0.0);
    if (all(lessThan(pixel, imageSize(hdrImage)))) {
        vec4 c = imageLoad(hdrImage, pixel);
        if (c.a > 0.5) v = vec2(log(1e-6 + dot(max(c.rgb, vec3(0.0)), vec3(0.2126, 0.7152, 0.0722))), 1.0);
    }
    uint i = gl_LocalInvocationIndex;
    sums[i] = v;
    barrier();
    for (uint s = 128u; s > 0u; s >>= 1u) {
        if (i < s) sums[i] += sums[i + s];
        barrier();
    }
    if (i == 0u) partials[gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x] = sums[0];
}
