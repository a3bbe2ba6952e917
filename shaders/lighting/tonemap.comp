#version 460
// HDR -> 8-bit sRGB. Radiance: exposure, then the ACES filmic fit of Narkowicz (2015),
// f(x) = x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14), clamped to [0,1], then the sRGB transfer curve.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "lighting/lighting_bindings.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = TONEMAP_HDR, rgba32f) uniform readonly image2D hdrImage;
layout(set = 0, binding = TONEMAP_LDR, rgba8) uniform writeonly image2D ldrImage;
layout(set = 0, binding = TONEMAP_EXPOSURE, std430) readonly buffer Exposure { AutoExposureState exposure; };
layout(push_constant) uniform Push { TonemapPush pc; };

vec3 acesFit(vec3 x) {
    return clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

vec3 srgbEncode(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, imageSize(ldrImage)))) return;
    vec3 c = imageLoad(hdrImage, pixel).rgb;
    uint mode = pc.mode;
    float scale = pc.autoExposure != 0u ? pc.scale * exposure.exposure : pc.scale;
    if (mode == TONEMAP_ACES) c = srgbEncode(acesFit(c * scale));
    else if (mode == TONEMAP_SRGB) c = srgbEncode(c);
    else c = clamp(c * pc.scale + pc.bias, 0.0, 1.0);
    imageStore(ldrImage, pixel, vec4(c, 1.0));
}
