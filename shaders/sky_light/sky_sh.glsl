// The sky's order-2 SH radiance (SkyLightPush.sh) evaluated in a direction, and the irradiance it
// gives a surface (Ramamoorthi and Hanrahan 2001: the cosine lobe's band factors pi, 2pi/3, pi/4).
// The basis is core/sky.h's shBasis, world axes.
#ifndef PENUMBRA_SKY_SH_GLSL
#define PENUMBRA_SKY_SH_GLSL

const float kSkyPi = 3.14159265358979;

void skyBasis(vec3 d, out float y[9]) {
    y[0] = 0.282095;
    y[1] = 0.488603 * d.y;
    y[2] = 0.488603 * d.z;
    y[3] = 0.488603 * d.x;
    y[4] = 1.092548 * d.x * d.y;
    y[5] = 1.092548 * d.y * d.z;
    y[6] = 0.315392 * (3.0 * d.z * d.z - 1.0);
    y[7] = 1.092548 * d.x * d.z;
    y[8] = 0.546274 * (d.x * d.x - d.y * d.y);
}

vec3 skyCoefficient(SkyLightPush p, int i) { return vec3(p.sh[3 * i], p.sh[3 * i + 1], p.sh[3 * i + 2]); }

// The radiance from direction d (clamped at 0: the truncated series rings below a sharp horizon).
vec3 skyRadiance(SkyLightPush p, vec3 d) {
    float y[9];
    skyBasis(d, y);
    vec3 l = vec3(0.0);
    for (int i = 0; i < 9; ++i) l += skyCoefficient(p, i) * y[i];
    return max(l, vec3(0.0));
}

// The irradiance of an unoccluded surface with normal n.
vec3 skyIrradiance(SkyLightPush p, vec3 n) {
    float y[9];
    skyBasis(n, y);
    const float band[9] = float[9](kSkyPi, 2.0 * kSkyPi / 3.0, 2.0 * kSkyPi / 3.0, 2.0 * kSkyPi / 3.0, kSkyPi / 4.0, kSkyPi / 4.0,
                                   kSkyPi / 4.0, kSkyPi / 4.0, kSkyPi / 4.0);
    vec3 e = vec3(0.0);
    for (int i = 0; i < 9; ++i) e += band[i] * skyCoefficient(p, i) * y[i];
    return max(e, vec3(0.0));
}
#endif
