// Shadow visibility as the lighting pass reads it (included by lighting/lighting.comp, which declares
// `shadowMask`, `lights` and `frame`). The filtering itself runs before, in its own pass
// (shadow/filter.comp: hard, PCF, PCSS, VSM, EVSM, MSM; cascades, cube faces, paraboloids), which
// leaves per shadowed light r = visibility, g = layer code in layer GpuLight.shadowIndex of the mask.
float shadowVisibility(GpuLight light, ivec2 pixel) {
    if (light.shadowIndex == NO_SHADOW) return 1.0;
    return texelFetch(shadowMask, ivec3(pixel, light.shadowIndex), 0).r;
}

// The first shadowed light's layer code at this pixel (layer + blend fraction; -1: no shadowed light).
float firstShadowLayer(ivec2 pixel) {
    for (uint i = 0u; i < frame.lightCount; ++i)
        if (lights[i].shadowIndex != NO_SHADOW)
            return texelFetch(shadowMask, ivec3(pixel, lights[i].shadowIndex), 0).g;
    return -1.0;
}

// `cascade` AOV: the first shadowed light's layer at this pixel as a colour (cascade 0 red, 1 green,
// 2 blue, 3 yellow, ...; blend bands mix neighbours; cube faces and hemispheres likewise), darkened
// where shadowed so that cascade borders can be judged against the shadows they carry.
vec3 shadowLayerColour(ivec2 pixel) {
    const vec3 palette[9] = vec3[](vec3(0.9, 0.2, 0.2), vec3(0.2, 0.8, 0.2), vec3(0.25, 0.4, 1.0),
                                   vec3(0.95, 0.85, 0.2), vec3(0.85, 0.3, 0.9), vec3(0.2, 0.85, 0.9),
                                   vec3(1.0, 0.55, 0.15), vec3(0.75, 0.75, 0.75), vec3(0.1, 0.1, 0.1));
    for (uint i = 0u; i < frame.lightCount; ++i) {
        if (lights[i].shadowIndex == NO_SHADOW) continue;
        vec2 m = texelFetch(shadowMask, ivec3(pixel, lights[i].shadowIndex), 0).rg;
        int k = min(int(m.y), 8);
        vec3 c = mix(palette[k], palette[min(k + 1, 8)], fract(m.y));
        return c * (0.35 + 0.65 * m.x);
    }
    return vec3(0.0);
}
