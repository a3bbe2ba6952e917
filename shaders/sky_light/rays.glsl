// The sky-visibility rays of a receiver, as sky_light/trace.comp casts them and weigh.comp counts
// them: bit k of a pixel's clear-ray mask is ray k of rayDirection(n, k, count, tileRank(texel)).
#ifndef PENUMBRA_SKY_RAYS_GLSL
#define PENUMBRA_SKY_RAYS_GLSL

// The 4x4 Bayer matrix's rank of a traced texel within its tile: neighbours take distant rotations.
float tileRank(ivec2 texel) {
    const uint bayer[16] = uint[16](0u, 8u, 2u, 10u, 12u, 4u, 14u, 6u, 3u, 11u, 1u, 9u, 15u, 7u, 13u, 5u);
    const ivec2 t = texel & (SKY_TILE - 1);
    return (float(bayer[t.y * SKY_TILE + t.x]) + 0.5) / float(SKY_TILE * SKY_TILE);
}

// Ray k of `count` about n: cosine-distributed, stratified in the polar angle, the golden angle apart
// in azimuth, the whole set turned by `rank` of a turn.
vec3 rayDirection(vec3 n, uint k, uint count, float rank) {
    const float u = (float(k) + rank) / float(count);
    const float phi = 6.28318530718 * (float(k) * 0.618034 + rank);
    const float r = sqrt(u);
    const vec3 t = normalize(abs(n.y) < 0.9 ? cross(n, vec3(0.0, 1.0, 0.0)) : cross(n, vec3(1.0, 0.0, 0.0)));
    const vec3 b = cross(n, t);
    return normalize(t * (r * cos(phi)) + b * (r * sin(phi)) + n * sqrt(max(1.0 - u, 0.0)));
}

// The camera pixel a traced texel stands for: the middle of its step x step block.
ivec2 tracedPixel(ivec2 texel, uint step) { return texel * int(step) + int(step / 2u); }
#endif
