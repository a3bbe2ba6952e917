// Hair ribbons rasterized in compute, 64 segments a workgroup (points i and i + 1 each): the pixels
// whose centres lie inside the segment's ribbon quad (dsm/ribbon.glsl, the quad the hardware strip
// draws), each handed to the includer's ribbonFragment(). Why: a ribbon one or two pixels wide is
// the hardware raster's worst case (2x2 quads a quarter covered, on a GPU whose raster path is
// narrow: at 25k strands the camera's hair pass took 4.4 ms and the light's 3.8 ms on the H100);
// a walk along the ribbon's long axis visits only the covered pixels.
//
// The walk steps through the pixel columns (or rows, whichever axis the quad is longer along) and
// fills, in each, the span between the quad's edges at the column's centre. Attributes follow the
// segment's centre line: the parameter of the pixel's projection onto it, made perspective-correct
// with 1/w. Segments are clipped to the near plane (z >= 0); fragments beyond the far plane or
// outside `size` are not emitted. Needs `draw`, dsm/ribbon.glsl and dsm/dsm_common.glsl.

// `segment`: the index of the segment's first point (what oit_shade.comp reads the strand's own
// transmittance at).
void ribbonFragment(ivec2 pixel, float ndcDepth, float viewerDepth, float alpha, vec3 world, vec3 tangent,
                    vec3 colour, uint segment);

struct RibbonEnd {
    GpuHairPoint point;
    RibbonSection section;
    vec4 clip;  // the centre point's
};

RibbonEnd ribbonEnd(GpuHairPoint point, mat4 viewProj) {
    RibbonEnd e;
    e.point = point;
    e.section = ribbonSection(point);
    e.clip = viewProj * vec4(point.position.xyz, 1.0);
    return e;
}

// The end moved to parameter s along the segment towards `other` (near-plane clipping).
RibbonEnd clipEnd(RibbonEnd e, RibbonEnd other, float s, mat4 viewProj) {
    e.point.position.xyz = mix(e.point.position.xyz, other.point.position.xyz, s);
    e.point.tangent.xyz = mix(e.point.tangent.xyz, other.point.tangent.xyz, s);
    e.section = ribbonSection(e.point);
    e.clip = viewProj * vec4(e.point.position.xyz, 1.0);
    return e;
}

vec2 toPixels(vec4 clip, vec2 size) { return (clip.xy / clip.w * 0.5 + 0.5) * size; }

// The segment of this invocation in a 2D dispatch (HairGpu::dispatchSegments); false past the end.
bool ribbonSegmentIndex(out uint i) {
    i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    return i + 1 < uint(points.length());
}

// A segment's quad in pixels and what its fragments interpolate, set up by one invocation and walked
// column by column by any (rasterRibbonSegments).
struct RibbonSpan {
    vec4 q01, q23;         // the quad's corners a-, a+, b+, b- in pixels
    vec4 pab;              // xy: the centre line's start a, zw: its direction b - a (pixels)
    vec4 clip;             // a and b: window depth (z / w), 1 / w
    vec4 depthAlpha;       // a and b: viewer depth (dsmDepth), alpha
    vec4 worldA, worldB;   // w of A: |b - a|^2 (pixels), w of B: the walked axis (0: x, 1: y)
    vec4 tangentA, tangentB;  // w of A: the first column, w of B: the segment (uint bits)
    vec4 colour;
};
shared RibbonSpan ribbonSpans[64];
shared uint ribbonColumns[65];  // exclusive prefix of the group's segments' column counts

// Sets up segment i's quad (points i and i + 1) in span; returns its column count (0: nothing drawn).
uint setupRibbonSpan(uint i, vec2 size, out RibbonSpan span) {
    mat4 viewProj = views.viewProj[draw.ids.x];
    RibbonEnd a = ribbonEnd(points[i], viewProj), b = ribbonEnd(points[i + 1], viewProj);
    if (a.section.drawn <= 0.0 || b.section.drawn <= 0.0) return 0u;  // a join between strands
    if (a.clip.z < 0.0 && b.clip.z < 0.0) return 0u;
    if (a.clip.z < 0.0) a = clipEnd(a, b, a.clip.z / (a.clip.z - b.clip.z), viewProj);
    if (b.clip.z < 0.0) b = clipEnd(b, a, b.clip.z / (b.clip.z - a.clip.z), viewProj);

    // The quad a-, a+, b+, b- in pixels (corners in order around it).
    vec2 q[4];
    float halfA = 0.5 * a.section.drawn, halfB = 0.5 * b.section.drawn;
    vec4 corners[4] = vec4[4](viewProj * vec4(a.point.position.xyz - a.section.side * halfA, 1.0),
                              viewProj * vec4(a.point.position.xyz + a.section.side * halfA, 1.0),
                              viewProj * vec4(b.point.position.xyz + b.section.side * halfB, 1.0),
                              viewProj * vec4(b.point.position.xyz - b.section.side * halfB, 1.0));
    for (int k = 0; k < 4; ++k) {
        if (corners[k].w <= 0.0) return 0u;  // a ribbon wider than its distance to the eye: not drawn
        q[k] = toPixels(corners[k], size);
    }
    vec2 lo = min(min(q[0], q[1]), min(q[2], q[3])), hi = max(max(q[0], q[1]), max(q[2], q[3]));
    // u: the axis walked (the longer extent), v: the span filled.
    int u = hi.x - lo.x >= hi.y - lo.y ? 0 : 1;
    vec2 pa = toPixels(a.clip, size), pb = toPixels(b.clip, size), ab = pb - pa;
    float invWa = 1.0 / a.clip.w, invWb = 1.0 / b.clip.w;
    int first = max(int(ceil(lo[u] - 0.5)), 0), last = min(int(floor(hi[u] - 0.5)), int(size[u]) - 1);
    if (last < first) return 0u;
    span.q01 = vec4(q[0], q[1]);
    span.q23 = vec4(q[2], q[3]);
    span.pab = vec4(pa, ab);
    span.clip = vec4(a.clip.z * invWa, b.clip.z * invWb, invWa, invWb);
    span.depthAlpha = vec4(dsmDepth(draw.viewer, a.point.position.xyz), dsmDepth(draw.viewer, b.point.position.xyz),
                           a.section.alpha, b.section.alpha);
    span.worldA = vec4(a.point.position.xyz, max(dot(ab, ab), 1e-12));
    span.worldB = vec4(b.point.position.xyz, float(u));
    span.tangentA = vec4(a.point.tangent.xyz, float(first));
    span.tangentB = vec4(b.point.tangent.xyz, uintBitsToFloat(i));
    span.colour = vec4(strands[uint(a.point.tangent.w)].rgb, 0.0);
    return uint(last - first + 1);
}

// The pixels of one column of a span: the span between the quad's edges at the column's centre.
void rasterRibbonColumn(RibbonSpan span, int column, vec2 size) {
    int u = int(span.worldB.w), v = 1 - u;
    vec2 q[4] = vec2[4](span.q01.xy, span.q01.zw, span.q23.xy, span.q23.zw);
    float c = float(column) + 0.5, vMin = 1e30, vMax = -1e30;
    for (int k = 0; k < 4; ++k) {
        vec2 e0 = q[k], e1 = q[(k + 1) & 3];
        if ((e0[u] - c) * (e1[u] - c) > 0.0 || e0[u] == e1[u]) continue;
        float y = e0[v] + (c - e0[u]) * (e1[v] - e0[v]) / (e1[u] - e0[u]);
        vMin = min(vMin, y), vMax = max(vMax, y);
    }
    int rowFirst = max(int(ceil(vMin - 0.5)), 0), rowLast = min(int(floor(vMax - 0.5)), int(size[v]) - 1);
    for (int row = rowFirst; row <= rowLast; ++row) {
        vec2 pixel;
        pixel[u] = c, pixel[v] = float(row) + 0.5;
        float screen = clamp(dot(pixel - span.pab.xy, span.pab.zw) / span.worldA.w, 0.0, 1.0);
        float s = screen * span.clip.w / mix(span.clip.z, span.clip.w, screen);  // perspective-correct
        float ndcDepth = mix(span.clip.x, span.clip.y, screen);
        if (ndcDepth > 1.0) continue;
        ribbonFragment(ivec2(pixel), ndcDepth, mix(span.depthAlpha.x, span.depthAlpha.y, s),
                       mix(span.depthAlpha.z, span.depthAlpha.w, s), mix(span.worldA.xyz, span.worldB.xyz, s),
                       normalize(mix(span.tangentA.xyz, span.tangentB.xyz, s)), span.colour.rgb,
                       floatBitsToUint(span.tangentB.w));
    }
}

// The group's 64 segments (this invocation's: ribbonSegmentIndex), their columns shared out among
// the invocations: each segment is set up by its own invocation, then every invocation takes every
// 64th column of all of them. A warp that walked its own segments' columns waited for its longest
// segment at every step (a segment's column count varies with its length on screen).
void rasterRibbonSegments(vec2 size) {
    uint i, local = gl_LocalInvocationIndex;
    RibbonSpan span;
    uint columns = ribbonSegmentIndex(i) ? setupRibbonSpan(i, size, span) : 0u;
    if (columns > 0u) ribbonSpans[local] = span;
    ribbonColumns[local + 1u] = columns;
    if (local == 0u) ribbonColumns[0] = 0u;
    barrier();
    for (uint step = 1u; step < 64u; step <<= 1) {  // inclusive prefix of ribbonColumns[1..64]
        uint add = local >= step ? ribbonColumns[local + 1u - step] : 0u;
        barrier();
        ribbonColumns[local + 1u] += add;
        barrier();
    }
    uint total = ribbonColumns[64];
    for (uint t = local; t < total; t += 64u) {
        uint lo = 0u, hi = 64u;  // the segment s with ribbonColumns[s] <= t < ribbonColumns[s + 1]
        while (hi - lo > 1u) {
            uint mid = (lo + hi) / 2u;
            if (ribbonColumns[mid] <= t) lo = mid; else hi = mid;
        }
        RibbonSpan s = ribbonSpans[lo];
        rasterRibbonColumn(s, int(s.tangentA.w) + int(t - ribbonColumns[lo]), size);
    }
}
