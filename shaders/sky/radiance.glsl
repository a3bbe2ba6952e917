// The sky's radiance towards a world direction from its equirectangular texture (names::kSkyRadiance,
// core/sky.h's layout): bilinear, wrapping in azimuth, clamped at the poles (texel fetches: a sampler
// cannot wrap one axis and clamp the other).
#ifndef PENUMBRA_SKY_RADIANCE_GLSL
#define PENUMBRA_SKY_RADIANCE_GLSL

vec3 skyTextureRadiance(sampler2D sky, vec3 d) {
    const float pi = 3.14159265358979;
    const ivec2 size = textureSize(sky, 0);
    const float theta = acos(clamp(d.y, -1.0, 1.0)), phi = atan(d.x, -d.z);
    const vec2 t = vec2((phi + pi) / (2.0 * pi), theta / pi) * vec2(size) - 0.5;
    const ivec2 i0 = ivec2(floor(t));
    const vec2 f = t - vec2(i0);
    vec3 sum = vec3(0.0);
    for (int k = 0; k < 4; ++k) {
        const ivec2 o = ivec2(k & 1, k >> 1);
        const ivec2 texel = ivec2((i0.x + o.x + size.x) % size.x, clamp(i0.y + o.y, 0, size.y - 1));
        const float w = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
        sum += w * texelFetch(sky, texel, 0).rgb;
    }
    return sum;
}
#endif
