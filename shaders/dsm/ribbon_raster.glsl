// Hair ribbons rasterized in compute, one invocation per segment (points i and i + 1): the pixels
// whose centres lie inside the segment's ribbon quad (dsm/ribbon.glsl, the quad the hardware strip
// draws), each handed to the includer's ribbonFragment(). Why: a ribbon one or two pixels wide is
// the hardware raster's worst case (2x2 quads a quarter covered, on a GPU whose raster path is
// narrow, where the hair's hardware passes were most of the hair frame); a walk along the ribbon's
// long axis visits only the covered pixels.
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
    e.clip = viewProj * vec4(point.position, 1.0);
    return e;
}

// The end moved to parameter s along the segment towards `other` (near-plane clipping).
RibbonEnd clipEnd(RibbonEnd e, RibbonEnd other, float s, mat4 viewProj) {
    e.point.position = mix(e.point.position, other.point.position, s);
    e.point.tangent = mix(e.point.tangent, other.point.tangent, s);
    e.section = ribbonSection(e.point);
    e.clip = viewProj * vec4(e.point.position, 1.0);
    return e;
}

vec2 toPixels(vec4 clip, vec2 size) { return (clip.xy / clip.w * 0.5 + 0.5) * size; }

void rasterRibbonSegment(uint i, vec2 size) {
    mat4 viewProj = views.viewProj[draw.viewRow];
    RibbonEnd a = ribbonEnd(points[i], viewProj), b = ribbonEnd(points[i + 1], viewProj);
    if (a.section.drawn <= 0.0 || b.section.drawn <= 0.0) return;  // a join between strands
    if (a.clip.z < 0.0 && b.clip.z < 0.0) return;
    if (a.clip.z < 0.0) a = clipEnd(a, b, a.clip.z / (a.clip.z - b.clip.z), viewProj);
    if (b.clip.z < 0.0) b = clipEnd(b, a, b.clip.z / (b.clip.z - a.clip.z), viewProj);

    // The quad a-, a+, b+, b- in pixels (corners in order around it).
    vec2 q[4];
    float halfA = 0.5 * a.section.drawn, halfB = 0.5 * b.section.drawn;
    vec4 corners[4] = vec4[4](viewProj * vec4(a.point.position - a.section.side * halfA, 1.0),
                              viewProj * vec4(a.point.position + a.section.side * halfA, 1.0),
                              viewProj * vec4(b.point.position + b.section.side * halfB, 1.0),
                              viewProj * vec4(b.point.position - b.section.side * halfB, 1.0));
    for (int k = 0; k < 4; ++k) {
        if (corners[k].w <= 0.0) return;  // a ribbon wider than its distance to the eye: not drawn
        q[k] = toPixels(corners[k], size);
    }
    vec2 lo = min(min(q[0], q[1]), min(q[2], q[3])), hi = max(max(q[0], q[1]), max(q[2], q[3]));
    // u: the axis walked (the longer extent), v: the span filled.
    bool alongX = hi.x - lo.x >= hi.y - lo.y;
    int u = alongX ? 0 : 1, v = 1 - u;
    vec2 pa = toPixels(a.clip, size), pb = toPixels(b.clip, size), ab = pb - pa;
    float invWa = 1.0 / a.clip.w, invWb = 1.0 / b.clip.w, len2 = max(dot(ab, ab), 1e-12);
    float depthA = dsmDepth(draw.view.viewer, draw.view.viewerIsPoint, a.point.position);
    float depthB = dsmDepth(draw.view.viewer, draw.view.viewerIsPoint, b.point.position);
    vec3 colour = strands[a.point.strand].color;

    int first = max(int(ceil(lo[u] - 0.5)), 0), last = min(int(floor(hi[u] - 0.5)), int(size[u]) - 1);
    for (int column = first; column <= last; ++column) {
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
            float screen = clamp(dot(pixel - pa, ab) / len2, 0.0, 1.0);
            float s = screen * invWb / mix(invWa, invWb, screen);  // perspective-correct
            float ndcDepth = mix(a.clip.z * invWa, b.clip.z * invWb, screen);
            if (ndcDepth > 1.0) continue;
            ribbonFragment(ivec2(pixel), ndcDepth, mix(depthA, depthB, s), mix(a.section.alpha, b.section.alpha, s),
                           mix(a.point.position, b.point.position, s),
                           normalize(mix(a.point.tangent, b.point.tangent, s)), colour, i);
        }
    }
}

// The segment of this invocation in a 2D dispatch (HairGpu::dispatchSegments); false past the end.
bool ribbonSegmentIndex(out uint i) {
    i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    return i + 1 < uint(points.length());
}
