// The receiver at a camera pixel, as both sky-light passes see it. The includer declares the frame
// uniform `frame` and the samplers gNormal and gDepth, and includes core/reconstruct.glsl.
#ifndef PENUMBRA_SKY_SURFACE_GLSL
#define PENUMBRA_SKY_SURFACE_GLSL

struct SkyReceiver {
    bool surface;
    vec3 p, n;
};

// A surface's normal turned toward the camera (two-sided, as the lighting shades it). A hair pixel
// (SHADING_HAIR) holds its tangent: it takes the sky as a surface facing the most upward of the
// directions across the strand, the side a strand's cylinder turns to the sky.
SkyReceiver skyReceiver(ivec2 pixel) {
    SkyReceiver r;
    const float depth = texelFetch(gDepth, pixel, 0).r;
    r.surface = depth < 1.0;
    r.p = vec3(0.0);
    r.n = vec3(0.0, 1.0, 0.0);
    if (!r.surface) return r;
    r.p = pixelWorldPosition(frame, pixel, depth);
    const vec4 g = texelFetch(gNormal, pixel, 0);
    const vec3 n = normalize(g.xyz);
    if (g.w > 1.5) {
        const vec3 across = vec3(0.0, 1.0, 0.0) - n * n.y;
        r.n = dot(across, across) > 1e-6 ? normalize(across) : vec3(1.0, 0.0, 0.0);
        return r;
    }
    r.n = dot(n, frame.eye - r.p) < 0.0 ? -n : n;
    return r;
}

// How much the sky share of receiver q counts at receiver r: by how near q lies to r's tangent plane
// (per cent of the distance) and how alike their normals are. Smooth, not a cut: bumpy shading
// normals and curved cloth would leave a cut with too few receivers and show the rays' pattern.
float surfaceWeight(SkyReceiver r, SkyReceiver q) {
    if (!q.surface) return 0.0;
    const float plane = abs(dot(q.p - r.p, r.n)) / max(length(frame.eye - r.p), 1e-4) / 0.02;
    const float facing = max(dot(q.n, r.n), 0.0);
    const float facing2 = facing * facing, facing4 = facing2 * facing2;
    return exp(-plane * plane) * facing4 * facing4;
}
#endif
