#version 460
// Debug views of light-space images (the RSM's depth, normal and flux, a shadow-map layer): one layer
// of the source, letterboxed as a square into the output image before tone mapping.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "lighting/lighting_bindings.h"
#include "shared/octahedral.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = DEBUG_VIEW_SOURCE) uniform sampler2DArray source;
layout(set = 0, binding = DEBUG_VIEW_OUT, rgba32f) uniform writeonly image2D outImage;
layout(push_constant) uniform Push { DebugViewPush pc; };

void main() {
    const ivec2 size = imageSize(outImage);
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, size))) return;
    const float side = float(min(size.x, size.y));
    const vec2 uv = (vec2(pixel) + 0.5 - 0.5 * (vec2(size) - side)) / side;
    vec3 value = vec3(0.0);
    if (all(greaterThanEqual(uv, vec2(0.0))) && all(lessThan(uv, vec2(1.0)))) {
        const vec4 texel = textureLod(source, vec3(uv, float(pc.layer)), 0.0);
        if (pc.aov == AOV_RSM_NORMAL) value = octDecode(texel.xy) * 0.5 + 0.5;
        else if (pc.aov == AOV_RSM_FLUX) {
            // A texel's flux shrinks with the texel count: shown as the intensity (W/sr) of a light that
            // sent every texel's flux over the sphere, so that the view reads alike at every resolution.
            const ivec3 texels = textureSize(source, 0);
            value = texel.rgb * float(texels.x * texels.y) / (4.0 * 3.14159265);
        }
        else value = vec3(texel.r);  // depth in [0, 1]
    }
    imageStore(outImage, pixel, vec4(value, 1.0));
}
