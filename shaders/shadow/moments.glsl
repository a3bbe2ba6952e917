// Filterable shadow maps: what the moments pass stores per texel and how the filter pass turns the
// filtered moments back into a visibility. Depth is linear in [0,1] between the layer's near and
// far (orthographic and paraboloid layers store it so; perspective depth is linearised first), so
// that a blur averages distances, not the hyperbolic depth of a perspective map.

// Floor of the variance (linear depth units squared): a flat receiver's own moments have zero
// variance, and float rounding must not make it shadow itself. 1e-8 is 1e-4 of the depth range.
const float SHADOW_MIN_VARIANCE = 1e-8;

float linearShadowDepth(GpuShadowLayer layer, float depth) {
    if (layer.projection != SHADOW_PROJ_PERSPECTIVE) return depth;
    float n = layer.zNear, f = layer.zFar;
    float z = n * f / (f - depth * (f - n));  // inverse of Vulkan's [0,1] perspective depth
    return (z - n) / (f - n);
}

// EVSM warp (Lauritzen & McCool 2008) of depth z in [0,1]: positive and negative exponentials of 2z - 1.
vec2 evsmWarp(float z, GpuMomentParams m) {
    float w = 2.0 * z - 1.0;
    return vec2(exp(m.evsmPositive * w), -exp(-m.evsmNegative * w));
}

// `m` = GpuShadowParams.moments.
vec4 encodeMoments(uint filterMode, float z, GpuMomentParams m) {
    if (filterMode == SHADOW_FILTER_VSM) return vec4(z, z * z, 0.0, 0.0);
    if (filterMode == SHADOW_FILTER_EVSM) {
        vec2 e = evsmWarp(z, m);
        return vec4(e.x, e.x * e.x, e.y, e.y * e.y);
    }
    // MSM: the first four power moments of depth mapped to [-1, 1], where they are best conditioned.
    float x = 2.0 * z - 1.0, x2 = x * x;
    return vec4(x, x2, x2 * x, x2 * x2);
}

// One-sided Chebyshev bound P(x >= t) <= var / (var + (t - mean)^2) (Donnelly & Lauritzen 2006).
float chebyshevUpperBound(vec2 moments, float t, float minVariance) {
    if (t <= moments.x) return 1.0;
    float variance = max(moments.y - moments.x * moments.x, minVariance);
    float d = t - moments.x;
    return variance / (variance + d * d);
}

// Light-bleeding reduction: the bound's low tail (where bleeding lives) is cut off and the rest
// stretched back to [0,1], i.e. linstep(amount, 1, p).
float reduceBleeding(float p, float amount) {
    return clamp((p - amount) / max(1.0 - amount, 1e-4), 0.0, 1.0);
}

float evsmVisibility(vec4 moments, float z, GpuMomentParams m) {
    vec2 e = evsmWarp(z, m);
    // The variance floor scales with the warp's slope at z (d/dz of the exponentials).
    vec2 slope = 2.0 * vec2(m.evsmPositive * e.x, m.evsmNegative * e.y);
    float pos = chebyshevUpperBound(moments.xy, e.x, SHADOW_MIN_VARIANCE * slope.x * slope.x);
    float neg = chebyshevUpperBound(moments.zw, e.y, SHADOW_MIN_VARIANCE * slope.y * slope.y);
    return min(pos, neg);
}

// Hamburger 4-moment shadow map (Peters & Klein 2015, algorithm 3): the lower bound on the fraction
// of occluders in front of z, from the 3-point distribution that matches the (biased) moments and
// has a node at z.
float msmVisibility(vec4 moments, float depth, float bias) {
    // Moments of depth in [-1, 1]; biased towards those of a well-spread distribution (the paper's
    // (0, 0.63, 0, 0.63)), which keeps the Hankel matrix positive definite in 32-bit floats.
    float z = 2.0 * depth - 1.0;
    vec4 b = mix(moments, vec4(0.0, 0.63, 0.0, 0.63), bias);
    // Cholesky factorisation of the Hankel matrix [1 b1 b2; b1 b2 b3; b2 b3 b4]: L D L^T.
    float d22 = b.y - b.x * b.x;
    float l32d22 = b.z - b.x * b.y;
    float l32 = l32d22 / d22;
    float d33d22 = (b.w - b.y * b.y) * d22 - l32d22 * l32d22;
    // Solve B c = (1, z, z^2): forward substitution, diagonal scaling, back substitution.
    vec3 c = vec3(1.0, z, z * z);
    c.y -= b.x;
    c.z -= b.y + l32 * c.y;
    c.y /= d22;
    c.z *= d22 / d33d22;
    c.y -= l32 * c.z;
    c.x -= dot(c.yz, b.xy);
    // The other two nodes are the roots of c.x + c.y x + c.z x^2.
    float p = c.y / c.z, q = c.x / c.z;
    float r = sqrt(max(0.25 * p * p - q, 0.0));
    float z1 = -0.5 * p - r, z2 = -0.5 * p + r;
    // Occluded fraction = total weight of the nodes in front of z: 0 when none is, the weight of z1
    // when z1 alone is, and 1 - the weight of z itself when both are. Each weight follows from
    // the first two moments: w(a) = (b c - b1 (b + c) + b2) / ((a - b)(a - c)) for nodes a, b, c.
    vec4 sw = z2 < z ? vec4(z1, z, 1.0, 1.0) : (z1 < z ? vec4(z, z1, 0.0, 1.0) : vec4(0.0));
    float quotient = (sw.x * z2 - b.x * (sw.x + z2) + b.y) / ((z2 - sw.y) * (z - z1));
    float occluded = clamp(sw.z + sw.w * quotient, 0.0, 1.0);
    return 1.0 - occluded;
}

// Visibility of linear depth z from filtered moments, with light-bleeding reduction.
float momentVisibility(uint filterMode, vec4 moments, float z, GpuMomentParams m) {
    float p;
    if (filterMode == SHADOW_FILTER_VSM) p = chebyshevUpperBound(moments.xy, z, SHADOW_MIN_VARIANCE);
    else if (filterMode == SHADOW_FILTER_EVSM) p = evsmVisibility(moments, z, m);
    else p = msmVisibility(moments, z, m.msmBias);
    return reduceBleeding(p, m.bleedReduction);
}
