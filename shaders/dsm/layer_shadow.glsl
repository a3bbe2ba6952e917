// The shadow of light `i` at a translucent layer or hair point p: its ordinary shadow map (filtered,
// `angle` the kernel's rotation) times its deep shadow map. n is the surface normal, or for hair
// (`hair`) the strand's tangent, whose receiver moves towards the light `l` instead. Needs
// shadow/visibility.glsl (and its bindings) and dsm/dsm_lookup.glsl.
float layerShadow(uint i, GpuLight light, vec3 p, vec3 n, vec3 l, bool hair, float angle) {
    float v = 1.0;
    if (light.shadowIndex != NO_SHADOW)
        v = lightVisibility(shadowLights[uint(light.shadowIndex)], light, p, hair ? l : n, angle, true).x;
    return v * deepShadowTransmittance(i, p, n, hair);
}
