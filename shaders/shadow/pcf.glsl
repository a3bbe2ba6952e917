// Depth-compare filters: hard, PCF (Reeves et al. 1987) with a rotated Poisson disc, PCSS
// (Fernando 2005). Needs `shadowDepth` (sampler2DArray, nearest,
// border 1: lit), `params` and project.glsl. Loops are kept rolled and every filter has one call site:
// lavapipe compiles shaders with LLVM at first use, and unrolled, inlined copies cost seconds there.
//
// Every tap is a world point: an offset from the receiver in the plane perpendicular to the light
// ray, moved along the light ray onto the receiver's tangent plane. Its projection then gives both
// the texel and the compare depth, so (1) a kernel has the same world size in every layer and
// crosses cube faces and the paraboloid seam like any other point, and (2) the reference depth
// follows a slanted receiver across the kernel instead of staying at the centre's depth (which
// would make wide kernels shadow their own receiver: "receiver-plane depth bias", done exactly).

// Kernel tap i (0..31): params.poisson, a progressive Poisson-disc set (see GpuShadowParams).
vec2 poissonTap(int i) {
    vec4 pair = params.poisson[i >> 1];
    return (i & 1) == 0 ? pair.xy : pair.zw;
}

// A receiver as the filters see it.
struct ShadowReceiver {
    vec3 p;          // world position, already moved along its normal by the normal offset
    vec3 n;          // unit normal
    vec3 lightPos;   // the light's position (local lights)
    vec3 rayDir;     // unit direction light -> receiver (directional: the light's direction)
    bool local;      // spot or point light: rays fan out from lightPos
    uint layer;      // the layer chosen for the pixel (spot, cascade); point lights choose per tap
    float texel;     // world size of a texel at p
    vec3 tangent, bitangent;  // basis of the plane perpendicular to rayDir
    float angle;     // per-pixel rotation of the kernel
};

// Bilinear PCF of one compare (2x2 texels) from a 4-texel gather of the stored depths, compared here:
// one path for every map format (the compute rasterizer's R32_SFLOAT maps cannot be sampled with a
// compare sampler, and lavapipe's D32_SFLOAT cannot be filtered linearly) and float weights (the
// hardware's bilinear compare quantises them, to 8 bits on NVIDIA).
float compareBilinear(ShadowCoord c) {
    float ref = min(c.depth, 1.0);  // beyond the far plane: compare against the far plane
    float res = float(params.resolution);
    vec2 t = c.uvLayer.xy * res - 0.5;
    vec2 f = fract(t);
    // Sample exactly at the corner shared by the 4 texels, so the gather picks the same 4 as floor(t).
    vec4 d = textureGather(shadowDepth, vec3((floor(t) + 1.0) / res, c.uvLayer.z));
    vec4 g = vec4(greaterThanEqual(d, vec4(ref)));  // lit where ref <= stored depth (LESS_OR_EQUAL)
    // Gather order: (i0, j1), (i1, j1), (i1, j0), (i0, j0).
    return mix(mix(g.w, g.z, f.x), mix(g.x, g.y, f.x), f.y);
}

float storedDepth(ShadowCoord c) { return texture(shadowDepth, c.uvLayer).r; }

// The tap at `offset` (in the plane perpendicular to the ray) moved along its light ray onto the
// receiver's tangent plane. Near grazing incidence the move is limited (the light is weak there).
vec3 tapPoint(ShadowReceiver r, vec2 offset) {
    vec3 q = r.p + r.tangent * offset.x + r.bitangent * offset.y;
    if (r.local) {
        float s = dot(r.p - r.lightPos, r.n) / dot(q - r.lightPos, r.n);
        return r.lightPos + (q - r.lightPos) * clamp(s, 0.5, 2.0);
    }
    float cosTheta = dot(r.rayDir, r.n);
    float t = -dot(q - r.p, r.n) / (abs(cosTheta) > 1e-3 ? cosTheta : 1e-3);
    float limit = 4.0 * length(offset);
    return q + r.rayDir * clamp(t, -limit, limit);
}

vec2 rotated(vec2 v, float angle) {
    float c = cos(angle), s = sin(angle);
    return vec2(c * v.x - s * v.y, s * v.x + c * v.y);
}

float hardVisibility(GpuShadowLight s, GpuLight light, ShadowReceiver r) {
    ShadowCoord c = shadowProject(shadowLayerFor(s, light, r.layer, r.p), r.p);
    return min(c.depth, 1.0) <= storedDepth(c) ? 1.0 : 0.0;
}

// PCF over a disc of world radius `radius` with the first `taps` Poisson taps.
float pcfVisibility(GpuShadowLight s, GpuLight light, ShadowReceiver r, float radius, int taps) {
    float sum = 0.0;
    [[dont_unroll]] for (int i = 0; i < taps; ++i) {
        vec3 q = tapPoint(r, rotated(poissonTap(i), r.angle) * radius);
        sum += compareBilinear(shadowProject(shadowLayerFor(s, light, r.layer, q), q));
    }
    return sum / float(taps);
}

// Distance of the receiver from the light, as shadowDistance measures blockers.
float receiverDistance(ShadowReceiver r) {
    if (r.local) return distance(r.p, r.lightPos);
    ShadowCoord c = shadowProject(r.layer, r.p);
    GpuShadowLayer layer = shadowLayers[r.layer];
    return layer.zNear + c.depth * (layer.zFar - layer.zNear);
}

// PCSS (blocker search and penumbra estimate): the PCF radius w / 2 from the penumbra width
// w = (d_receiver - d_blocker) * size / d_blocker by similar triangles (a local light of diameter
// `size`), or w = (d_receiver - d_blocker) * 2 tan(angular radius) for a directional light.
// Returns 0 when no blocker is found (fully lit).
float pcssRadius(GpuShadowLight s, GpuLight light, ShadowReceiver r) {
    float size = s.penumbraScale;
    float dr = receiverDistance(r);
    float maxRadius = params.pcssMaxRadius * r.texel;
    // Blockers can sit anywhere between the light's near plane (the top of the scene for a
    // directional light) and the receiver: the search region is the light's footprint seen from
    // the receiver there, limited to the configured radius.
    float nearDistance = shadowLayers[r.layer].zNear;
    float search = 0.5 * size * (dr - nearDistance) / (r.local ? max(nearDistance, 1e-6) : 1.0);
    search = min(search, maxRadius);
    float blockerSum = 0.0;
    int blockers = 0;
    [[dont_unroll]] for (int i = 0; i < 16; ++i) {
        vec3 q = tapPoint(r, rotated(poissonTap(i), r.angle) * search);
        uint layer = shadowLayerFor(s, light, r.layer, q);
        ShadowCoord c = shadowProject(layer, q);
        float stored = storedDepth(c);
        if (stored < min(c.depth, 1.0)) {
            blockerSum += shadowDistance(layer, stored, q, r.lightPos);
            ++blockers;
        }
    }
    if (blockers == 0) return 0.0;
    float db = blockerSum / float(blockers);
    float w = r.local ? (dr - db) * size / max(db, 1e-6) : (dr - db) * size;
    return clamp(0.5 * w, r.texel, maxRadius);
}
