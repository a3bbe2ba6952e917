// The irradiance a receiver takes from a summed light volume (lpv.h): read trilinearly at the receiver
// moved one cell along its normal (against leaking through thin walls, and away from the cell its own
// VPLs were injected into, half a cell out, whose outgoing L1 lobe cancels the light coming in: with
// half a cell the GI suite's room is 28% too dark; the price, a brighter near field:
// docs/techniques/lpv.md), E = max(0, dot(I, CosineLobe(-n))) / cell^2 (intensity per cell
// cross-section is radiance; the clamped-cosine integral against it is irradiance), summed over the
// cascades. Shared by the gather and the temporal gradients, which read two volumes: the includer
// defines, before it, `pc` (LpvPush: resolution, cascade count, blend band) and for volume `v`
// GpuLpvCascade lpvCascade(uint v, uint k), the placement of its cascade k, and
// vec4 lpvSum(uint v, uint index), its summed light at lightIndex-style `index`.

// `half_` 0: the near half of the running sum (every step of cascade 0), 1: the far half (lpv.h).
vec3 irradianceIn(uint v, uint k, uint half_, vec3 x, vec3 n, bool hair) {
    uint offset = half_ * 3u * pc.cascadeCount * cellsPerVolume();
    GpuLpvCascade cascade = lpvCascade(v, k);
    vec3 g = gridCoord(cascade, x) - 0.5;
    ivec3 base = ivec3(floor(g));
    vec3 f = g - vec3(base);
    vec4 lobe = hair ? hairLobe() : cosineLobe(-n);
    vec3 e = vec3(0.0);
    for (int i = 0; i < 8; ++i) {
        ivec3 o = ivec3(i & 1, (i >> 1) & 1, i >> 2);
        ivec3 c = clamp(base + o, ivec3(0), ivec3(pc.resolution) - 1);
        vec3 w3 = mix(1.0 - f, f, vec3(o));
        float w = w3.x * w3.y * w3.z;
        for (uint ch = 0; ch < 3u; ++ch) e[ch] += w * dot(lpvSum(v, offset + lightIndex(k, ch, c)), lobe);
    }
    float cell = cascade.cellSize;
    return max(e, vec3(0.0)) / (cell * cell);
}

// 1 deep inside cascade k of volume v, falling to 0 over the last `band` cells before its border.
float insideWeight(uint v, uint k, vec3 x) {
    vec3 g = gridCoord(lpvCascade(v, k), x);
    float inside = min(min(g.x, min(g.y, g.z)), float(pc.resolution) - max(g.x, max(g.y, g.z)));
    return clamp((inside - 1.0) / pc.blendCells, 0.0, 1.0);
}

// Cascades add up: each coarser one carries only the light that has gone beyond the reach of the
// finer one's steps (its far half), plus its near half where the finer one does not hold the
// receiver (outside it, blended over the border band). The outermost holds whatever is left.
// A hair receiver (`hair`, n its tangent) has no side to step towards: it reads the cells at x.
vec3 lpvIrradiance(uint v, vec3 x, vec3 n, bool hair) {
    vec3 e = vec3(0.0);
    float finer = 0.0;  // how much the next finer cascade holds x
    for (uint k = 0; k < pc.cascadeCount; ++k) {
        float inside = k + 1u == pc.cascadeCount ? 1.0 : insideWeight(v, k, x);
        vec3 p = hair ? x : x + lpvCascade(v, k).cellSize * n;
        if (k > 0u && inside > 0.0) e += inside * irradianceIn(v, k, 1u, p, n, hair);
        if (finer < 1.0 && inside > 0.0) e += inside * (1.0 - finer) * irradianceIn(v, k, 0u, p, n, hair);
        finer = inside;
    }
    return e;
}

// The receiver a G-buffer pixel holds (false: none, the sky): its position, its normal turned
// towards the eye, or a hair strand's tangent. Needs `frame`, `gNormal` and `gDepth`.
bool lpvReceiver(ivec2 pixel, out vec3 x, out vec3 n, out bool hair) {
    float depth = texelFetch(gDepth, pixel, 0).r;
    x = vec3(0.0);
    n = vec3(0.0);
    hair = false;
    if (depth >= 1.0) return false;
    x = pixelWorldPosition(frame, pixel, depth);
    vec4 g = texelFetch(gNormal, pixel, 0);
    n = normalize(g.xyz);
    hair = g.w > 1.5;  // SHADING_HAIR (--translucency off): n is the strand's tangent
    if (!hair && dot(n, frame.eye - x) < 0.0) n = -n;
    return true;
}
