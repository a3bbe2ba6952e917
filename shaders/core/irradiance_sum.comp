#version 460
// The sum of two indirect-irradiance contributions per pixel (core/irradiance_sum.h): each sampled
// at the output pixel's centre, so contributions of another resolution are filtered to it.
#extension GL_GOOGLE_include_directive : require
#include "core/irradiance_sum_bindings.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = IRRADIANCE_SUM_FIRST) uniform sampler2D first;
layout(set = 0, binding = IRRADIANCE_SUM_SECOND) uniform sampler2D second;
layout(set = 0, binding = IRRADIANCE_SUM_OUT, rgba32f) uniform writeonly image2D sum;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(sum);
    if (any(greaterThanEqual(pixel, size))) return;
    vec2 uv = (vec2(pixel) + 0.5) / vec2(size);
    vec3 e = textureLod(first, uv, 0.0).rgb + textureLod(second, uv, 0.0).rgb;
    imageStore(sum, pixel, vec4(e, 1.0));
}
