// Filtered shadow visibility of a world point (hard, PCF, PCSS, VSM, EVSM, MSM; cascades with their
// blend band, cube faces, paraboloids): shared by shadow/filter.comp (per G-buffer pixel) and the
// camera translucency (dsm/oit_shade.comp, per translucent fragment). Needs `frame`,
// `shadowLayers`, `shadowLights`, `params`, `shadowDepth`, `shadowMoments`, and
// project.glsl, moments.glsl, pcf.glsl included before.

ShadowReceiver makeReceiver(GpuShadowLight s, GpuLight light, uint layer, vec3 p, vec3 n, float angle) {
    ShadowReceiver r;
    r.local = light.type != LIGHT_DIRECTIONAL;
    r.lightPos = light.position;
    r.layer = shadowLayerFor(s, light, layer, p);
    r.texel = shadowTexelAt(r.layer, p, r.lightPos);
    r.p = p + n * (s.normalOffset * r.texel);
    r.n = n;
    r.rayDir = r.local ? normalize(r.p - r.lightPos) : light.direction;
    vec3 helper = abs(r.rayDir.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    r.tangent = normalize(cross(r.rayDir, helper));
    r.bitangent = cross(r.rayDir, r.tangent);
    r.angle = angle;
    return r;
}

float momentsLookup(GpuShadowLight s, GpuLight light, ShadowReceiver r) {
    uint layerIndex = shadowLayerFor(s, light, r.layer, r.p);
    ShadowCoord c = shadowProject(layerIndex, r.p);
    GpuShadowLayer layer = shadowLayers[layerIndex];
    if (any(lessThan(c.uvLayer.xy, vec2(0.0))) || any(greaterThan(c.uvLayer.xy, vec2(1.0)))) return 1.0;
    vec4 m = texture(shadowMoments, vec3(c.uvLayer.xy, float(layer.momentLayer)));
    return momentVisibility(s.filterMode, m, clamp(linearShadowDepth(layer, c.depth), 0.0, 1.0), params.moments);
}

float visibilityIn(GpuShadowLight s, GpuLight light, uint layer, vec3 p, vec3 n, float angle) {
    ShadowReceiver r = makeReceiver(s, light, layer, p, n, angle);
    uint mode = s.filterMode;
    if (mode >= SHADOW_FILTER_VSM) return momentsLookup(s, light, r);
    if (mode == SHADOW_FILTER_HARD) return hardVisibility(s, light, r);
    float radius = params.pcfRadius * r.texel;
    int taps = 16;
    if (mode == SHADOW_FILTER_PCSS) {
        radius = pcssRadius(s, light, r);
        if (radius <= 0.0) return 1.0;  // no blocker
        taps = 32;
    }
    return pcfVisibility(s, light, r, radius, taps);
}

// The layer(s) of the pixel: for cascades, cascade i by view depth, and in the last `blend`
// fraction of its range also cascade i + 1 (whose sphere was fit to include that band) with weight
// t; for point lights the face or hemisphere of p. Returns (visibility, layer code). `visible` =
// false: only the layer code is wanted (the light does not reach the pixel).
vec2 lightVisibility(GpuShadowLight s, GpuLight light, vec3 p, vec3 n, float angle, bool visible) {
    uint layer = shadowLayerFor(s, light, s.firstLayer, p);
    float t = 0.0, code = float(layer - s.firstLayer);
    if (s.kind == SHADOW_KIND_CASCADES) {
        float viewDepth = (frame.viewProj * vec4(p, 1.0)).w;
        uint count = s.layerCount, i = 0u;
        while (i + 1u < count && viewDepth > shadowLayers[s.firstLayer + i].splitFar) ++i;
        float splitNear = shadowLayers[s.firstLayer + i].splitNear, splitFar = shadowLayers[s.firstLayer + i].splitFar;
        if (viewDepth > splitFar) return vec2(1.0, 8.0);  // beyond the shadowed distance (code 8: grey)
        float band = params.cascadeBlend * (splitFar - splitNear);
        if (i + 1u < count && band > 0.0) t = clamp((viewDepth - (splitFar - band)) / band, 0.0, 1.0);
        layer = s.firstLayer + i;
        code = float(i) + t;
    }
    if (!visible) return vec2(0.0, code);
    float v = 0.0;
    [[dont_unroll]] for (uint k = 0u; k < (t > 0.0 ? 2u : 1u); ++k)
        v += (k == 0u ? 1.0 - t : t) * visibilityIn(s, light, layer + k, p, n, angle);
    return vec2(v, code);
}

// Interleaved gradient noise (Jimenez 2014): a per-pixel kernel rotation whose error is high
// frequency, so that a few taps give noise instead of banding.
float kernelAngle(ivec2 pixel) {
    return 6.28318531 * fract(52.9829189 * fract(dot(vec2(pixel), vec2(0.06711056, 0.00583715))));
}
