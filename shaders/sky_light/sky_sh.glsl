// The sky's order-2 SH radiance (names::kSkySh, bound at SKY_SH_BINDING by the shader that includes
// this) evaluated in a direction, and the irradiance it gives a surface (Ramamoorthi and Hanrahan
// 2001: the cosine lobe's band factors pi, 2pi/3, pi/4). The basis is core/sky.h's shBasis, world axes.
#ifndef PENUMBRA_SKY_SH_GLSL
#define PENUMBRA_SKY_SH_GLSL

#include "sky/sh_basis.glsl"

layout(set = 0, binding = SKY_SH_BINDING) uniform SkySh { vec4 skyCoefficients[9]; };

const float kSkyPi = 3.14159265358979;

// The radiance from direction d (clamped at 0: the truncated series rings below a sharp horizon).
vec3 skyRadiance(vec3 d) {
    float y[9];
    skyBasis(d, y);
    vec3 l = vec3(0.0);
    for (int i = 0; i < 9; ++i) l += skyCoefficients[i].rgb * y[i];
    return max(l, vec3(0.0));
}

// The irradiance of an unoccluded surface with normal n.
vec3 skyIrradiance(vec3 n) {
    float y[9];
    skyBasis(n, y);
    const float band[9] = float[9](kSkyPi, 2.0 * kSkyPi / 3.0, 2.0 * kSkyPi / 3.0, 2.0 * kSkyPi / 3.0, kSkyPi / 4.0, kSkyPi / 4.0,
                                   kSkyPi / 4.0, kSkyPi / 4.0, kSkyPi / 4.0);
    vec3 e = vec3(0.0);
    for (int i = 0; i < 9; ++i) e += band[i] * skyCoefficients[i].rgb * y[i];
    return max(e, vec3(0.0));
}
#endif
