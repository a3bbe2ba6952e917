// Shadow-map visibility of one light at a receiver (included by render/lighting.comp, which
// declares `shadowMaps`, a sampler2DArrayShadow with one layer per shadowed light).
// Visibility from the light's standard shadow map; the receiver is pushed along its normal by a
// number of shadow texels (normal offset), which removes acne on slopes without peter-panning.
float shadowVisibility(GpuLight light, vec3 p, vec3 n) {
    if (light.radiance.w == NO_SHADOW) return 1.0;
    float texel = light.shadow.x;
    if (light.spot.w > 0.5) texel *= max(dot(p - light.position.xyz, light.direction.xyz), 0.0);
    vec4 clip = light.shadowViewProj * vec4(p + n * (light.spot.z * texel), 1.0);
    vec3 ndc = clip.xyz / clip.w;
    vec2 uv = ndc.xy * 0.5 + 0.5;
    if (clip.w <= 0.0 || any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || ndc.z > 1.0)
        return 1.0;
    return texture(shadowMaps, vec4(uv, light.radiance.w, ndc.z));
}

