// Triangle setup of the compute rasterizer (src/raster), shared by the setup pass (raster/setup.comp)
// and the overflow pass (raster/overflow.comp), which sets up again the triangles of the pairs whose
// large triangles did not fit the tile lists.
// Transforms with the layer's views row (the shadow pass's matrices), rejects triangles outside the
// view, clips the rest against the view volume (the viewport, near and far planes, as lavapipe's
// clipper does: the depth planes of clipped triangles then come from the same vertices), culls back
// faces of single-sided materials with the shadow pass's winding (clockwise fronts), and hands each
// resulting triangle to the including pass's takeTriangle.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "raster/raster.glsl"
#include "core/instances.glsl"

#include "raster/bindings.h"
layout(set = 0, binding = RASTER_SET_VERTICES, std430) readonly buffer Vertices { float vertexData[]; };  // penumbra::Vertex
layout(set = 0, binding = RASTER_SET_INDICES, std430) readonly buffer Indices { uint indices[]; };
layout(set = 0, binding = RASTER_SET_TRIANGLE_MATERIALS, std430) readonly buffer TriangleMaterials { uint triangleMaterials[]; };
layout(set = 0, binding = RASTER_SET_LAYERS, std430) readonly buffer Layers { RasterLayer rasterLayers[]; };
layout(set = 0, binding = RASTER_SET_DRAWN_TRIANGLES, std430) readonly buffer DrawnTriangles { uvec2 drawnTriangles[]; };  // (instance, triangle)
layout(push_constant) uniform Push { RasterPush push; };
// (triangle, layer row) pairs whose large triangles did not fit the lists (raster/overflow.comp): the
// medium queue in the first half, the huge queue in the second.
layout(set = 0, binding = RASTER_SET_OVERFLOW_PAIRS, std430) buffer OverflowPairs { uvec2 overflowPairs[]; };
uint overflowQueueCapacity() { return uint(overflowPairs.length()) / 2u; }

// The tiles of a set-up triangle's box.
uint boxTiles(Edges e) {
    const ivec4 tiles = e.bbox / RASTER_TILE_SIZE;
    return uint((tiles.z - tiles.x + 1) * (tiles.w - tiles.y + 1));
}

const int kVertexFloats = 8;  // position xyz, normal xyz, uv
const int kMaxPolygon = 9;    // a triangle clipped by 6 planes

struct ClipVertex {
    vec4 position;  // clip space
    vec2 uv;
    bool made;      // made by the clipper (its window position is computed as the reference's clipper does)
};

// World, then clip space, in two products as the hardware's vertex shader takes them (shadow.vert):
// one product by view * model would round differently.
ClipVertex fetch(uint index, int instance, mat4 viewProj) {
    const uint base = index * kVertexFloats;
    const vec3 p = vec3(vertexData[base], vertexData[base + 1], vertexData[base + 2]);
    const vec4 clip = viewProj * vec4(instanceWorld(instance, p), 1.0);
    return ClipVertex(clip, vec2(vertexData[base + 6], vertexData[base + 7]), false);
}

// Signed distances to the view volume's planes, in the order and arithmetic of lavapipe's clipper
// (gallium draw: x <= w, x >= -w, y <= w, y >= -w, z >= 0, z <= w), which clips against the viewport
// itself, not a guard band: the same clipped vertices give the same depth planes.
float planeDistance(vec4 c, int plane) {
    switch (plane) {
        case 0: return c.w - c.x;
        case 1: return c.x + c.w;
        case 2: return c.w - c.y;
        case 3: return c.y + c.w;
        case 4: return c.z;
        default: return c.w - c.z;
    }
}

uint outcode(vec4 c) {
    uint code = 0u;
    for (int p = 0; p < 6; ++p)
        if (planeDistance(c, p) < 0.0) code |= 1u << p;
    return code;
}

// Window position (x, y in pixels, z = depth, w = 1/w) of a clip-space vertex: the viewport
// transform as lavapipe's draw module computes it (1/w once; fused scale-and-translate for the vertex
// shader's outputs, separate operations for the clipper's new vertices).
vec4 toWindow(ClipVertex v, vec2 halfSize) {
    precise const float oow = 1.0 / v.position.w;
    precise const vec3 ndc = v.position.xyz * oow;
    precise const vec2 xy = v.made ? ndc.xy * halfSize + halfSize : fma(ndc.xy, halfSize, halfSize);
    return vec4(xy, ndc.z, oow);
}

// Plane (value at v0, d/dx, d/dy) of a value given at three window positions.
vec3 plane(vec3 a, vec2 p0, vec2 p1, vec2 p2, float invDet) {
    const vec2 e1 = p1 - p0, e2 = p2 - p0;
    const float d1 = a.y - a.x, d2 = a.z - a.x;
    return vec3(a.x, (d1 * e2.y - d2 * e1.y) * invDet, (e1.x * d2 - e2.x * d1) * invDet);
}

// Vulkan's depth bias of a D32_SFLOAT buffer, r * constant + m * slope, with lavapipe's choices
// (llvmpipe's triangle setup) where the spec leaves them open: m = max(|dz/dx|, |dz/dy|) from the
// unsnapped window vertices (cross products times 1/area), r = 2^(e - 23) with e the exponent of the
// largest |z| (0 below the smallest normal), no clamp (the passes set depthBiasClamp 0).
float depthBias(vec3 p0, vec3 p1, vec3 p2, vec3 d01, vec3 d20, float ooa) {
    if (push.biasConstant == 0.0 && push.biasSlope == 0.0) return 0.0;  // no bias: no 0 * inf on degenerate planes
    precise const float dzdx = abs((d20.z * d01.y - d20.y * d01.z) * ooa);
    precise const float dzdy = abs((d20.x * d01.z - d20.z * d01.x) * ooa);
    const float maxZ = max(abs(p2.z), max(abs(p0.z), abs(p1.z)));
    const float r = intBitsToFloat(max((floatBitsToInt(maxZ) & 0x7F800000) - (23 << 23), 0));
    precise const float bias = r * push.biasConstant + max(dzdx, dzdy) * push.biasSlope;  // unclamped
    return bias;
}

// Depth plane (x: value at integer pixel coordinates (0, 0), y: d/dx, z: d/dy; w: depth bias) in the
// arithmetic of lavapipe's triangle setup (llvmpipe lp_state_setup.c): float, unfused, gradients
// from the unsnapped window vertices in its order, extrapolated from v0 (centres at + 0.5). The
// sample then evaluates fma(dz/dy, y, fma(dz/dx, x, a0)) + bias at the pixel's integer (x, y), as
// the reference's interpolator does. Following its order (not a better-conditioned one) is what
// keeps steep and huge triangles within float rounding of the hardware.
vec4 depthPlane(vec3 p0, vec3 p1, vec3 p2) {
    precise const vec3 d01 = p0 - p1, d20 = p2 - p0;
    precise const float ooa = 1.0 / (d01.x * d20.y - d01.y * d20.x);
    precise const vec2 d20ooa = d20.xy * ooa, d01ooa = d01.xy * ooa;
    precise const float dzdx = d01.z * d20ooa.y - d20.z * d01ooa.y;
    precise const float dzdy = d20.z * d01ooa.x - d01.z * d20ooa.x;
    precise const float a0 = p0.z - (dzdx * (p0.x - 0.5) + dzdy * (p0.y - 0.5));
    return vec4(a0, dzdx, dzdy, depthBias(p0, p1, p2, d01, d20, ooa));
}

// What the setup of one triangle needs besides its vertices.
struct Caster {
    uint layer, material;
    bool singleSided, alphaTested;
    bool flipped;  // fronts counter-clockwise: the camera's y-flipped projection xor a mirroring instance
    uvec2 ids;     // the visibility ID (core/visibility.glsl) and ID layer + 1
};

// Snapped window position (subpixel units, pixel centres at + half a pixel): lavapipe snaps
// round((x - 0.5) * 2^bits) (llvmpipe's fixed positions), to the nearest even on ties.
ivec2 snap(vec2 w, int bits) {
    return ivec2(roundEven((w - 0.5) * float(1 << bits))) + (1 << (bits - 1));
}

// What the including pass does with a set-up triangle (setup.comp: rasterize it if small, else bin
// it; overflow.comp: rasterize its part of a large one).
void takeTriangle(RasterTriangle t, Edges e, int bits, ivec2 size);

// Whether a set-up triangle is small: rasterized by the thread that set it up (bounded work).
bool isSmall(Edges e) {
    const int smallExtent = int(push.smallExtent);
    return e.bbox.z - e.bbox.x < smallExtent && e.bbox.w - e.bbox.y < smallExtent;
}

// One triangle of the clipped polygon, in clip space.
void emitTriangle(ClipVertex c0, ClipVertex c1, ClipVertex c2, Caster caster) {
    const ivec2 size = ivec2(push.width, push.height);
    const int bits = int(push.subpixelBits);
    const vec2 halfSize = 0.5 * vec2(size);
    vec4 w0 = toWindow(c0, halfSize), w1 = toWindow(c1, halfSize), w2 = toWindow(c2, halfSize);
    ivec2 s0 = snap(w0.xy, bits), s1 = snap(w1.xy, bits), s2 = snap(w2.xy, bits);
    const int64_t area = int64_t(s1.x - s0.x) * int64_t(s2.y - s0.y) - int64_t(s1.y - s0.y) * int64_t(s2.x - s0.x);
    // Fronts are clockwise in light views, counter-clockwise where the projection flips y (the camera).
    const bool back = caster.flipped ? area > 0l : area < 0l;
    if (area == 0l || (back && caster.singleSided)) return;  // empty, or a culled back face
    // lavapipe sets up (v0, v1, v2) when its area (the negative of this one) is positive, else (v0, v2, v1).
    const vec4 depth = area > 0l ? depthPlane(w0.xyz, w2.xyz, w1.xyz) : depthPlane(w0.xyz, w1.xyz, w2.xyz);
    if (area < 0l) {  // reorder to the positive winding the edges expect
        ClipVertex ct = c1; c1 = c2; c2 = ct;
        vec4 wt = w1; w1 = w2; w2 = wt;
        ivec2 st = s1; s1 = s2; s2 = st;
    }
    const Edges e = makeEdges(s0, s1, s2, bits, size);
    if (e.bbox.x > e.bbox.z || e.bbox.y > e.bbox.w) return;
    const float det = (w1.x - w0.x) * (w2.y - w0.y) - (w2.x - w0.x) * (w1.y - w0.y);
    if (det == 0.0) return;
    const float invDet = 1.0 / det;
    RasterTriangle t;
    t.vertex0 = s0;
    t.vertex1 = s1;
    t.vertex2 = s2;
    t.layer = caster.layer;
    t.material = caster.material;
    t.origin = w0.xy;
    t.alphaTested = caster.alphaTested ? 1u : 0u;
    t.firstEntry = RASTER_NO_ENTRY;
    t.depthPlane = depth.xyz;
    t.depthBias = depth.w;
    const vec3 iw = vec3(w0.w, w1.w, w2.w);
    t.invW = plane(iw, w0.xy, w1.xy, w2.xy, invDet);
    t.uOverW = plane(vec3(c0.uv.x, c1.uv.x, c2.uv.x) * iw, w0.xy, w1.xy, w2.xy, invDet);
    t.vOverW = plane(vec3(c0.uv.y, c1.uv.y, c2.uv.y) * iw, w0.xy, w1.xy, w2.xy, invDet);
    t.pad0 = t.pad1 = t.pad2 = t.pad3 = t.pad4 = 0u;
    t.visibilityId = caster.ids.x;
    t.idLayerPlusOne = caster.ids.y;
    takeTriangle(t, e, bits, size);
}

// The vertex where edge a -> b crosses a plane (distances da, db of opposite signs), as lavapipe's
// clipper makes it: from the vertex nearer the plane (on a tie the inside one), t = d_near / (d_near
// - d_far), near + t * (far - near) in clip space.
ClipVertex clipVertex(ClipVertex a, ClipVertex b, float da, float db) {
    const bool fromB = da >= 0.0 ? -db < da : !(-da < db);
    const ClipVertex near = fromB ? b : a, far = fromB ? a : b;
    precise const float t = (fromB ? db : -da) / (db - da);
    precise const vec4 position = near.position + t * (far.position - near.position);
    precise const vec2 uv = near.uv + t * (far.uv - near.uv);
    return ClipVertex(position, uv, true);
}

// Sutherland-Hodgman against the planes in `planes` (in plane order), then a fan of triangles from
// the first vertex: the polygons and triangles of lavapipe's clipper.
void clipAndEmit(ClipVertex v[3], uint planes, Caster caster) {
    ClipVertex poly[kMaxPolygon], next[kMaxPolygon];
    int n = 3;
    for (int i = 0; i < 3; ++i) poly[i] = v[i];
    for (int p = 0; p < 6 && n >= 3; ++p) {
        if ((planes & (1u << p)) == 0u) continue;
        int m = 0;
        for (int i = 0; i < n; ++i) {
            const ClipVertex a = poly[i], b = poly[(i + 1) % n];
            const float da = planeDistance(a.position, p), db = planeDistance(b.position, p);
            if (da >= 0.0) next[m++] = a;
            if ((da >= 0.0) != (db >= 0.0) && m < kMaxPolygon) next[m++] = clipVertex(a, b, da, db);
        }
        n = m;
        for (int i = 0; i < n; ++i) poly[i] = next[i];
    }
    for (int i = 1; i + 1 < n; ++i) emitTriangle(poly[0], poly[i], poly[i + 1], caster);
}

void setupTriangle(uint drawn, RasterLayer target) {
    const uvec2 ref = drawnTriangles[drawn];
    const uint triangle = ref.y;
    const uint material = triangleMaterials[triangle];
    const GpuMaterial m = materials[material];
    if (m.alphaMode == ALPHA_BLEND && target.skipBlended != 0u) return;  // a deep shadow map takes it
    const mat4 viewProj = views.viewProj[target.viewRow];
    ClipVertex v[3];  // in index order, as the hardware gets them (its plane setup depends on the order)
    for (int i = 0; i < 3; ++i) v[i] = fetch(indices[triangle * 3 + i], int(ref.x), viewProj);
    const uint c0 = outcode(v[0].position), c1 = outcode(v[1].position), c2 = outcode(v[2].position);
    if ((c0 & c1 & c2) != 0u) return;  // entirely outside one plane
    // A mirroring instance turns its fronts' winding, as the hardware's cull-mode flip takes it.
    const bool mirrored = instances[ref.x].mirrored != 0u;
    const Caster caster = Caster(target.targetLayer, material, m.doubleSided == 0u, m.alphaMode == ALPHA_MASK,
                                 (push.frontsCounterClockwise != 0u) != mirrored, uvec2(drawn + 1u, target.idLayerPlusOne));
    if ((c0 | c1 | c2) == 0u)
        emitTriangle(v[0], v[1], v[2], caster);
    else
        clipAndEmit(v, c0 | c1 | c2, caster);
}

