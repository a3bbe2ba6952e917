#version 460
// Triangle setup of the compute rasterizer (src/raster): one thread per (triangle, layer), every
// layer of every light in one dispatch (y = row of the layer table).
// Transforms with the layer's views row (the shadow pass's matrices), rejects triangles outside the
// view, clips the rest against the near and far planes and a guard band, culls back faces of
// single-sided materials with the shadow pass's winding (clockwise fronts), and then either
// rasterizes the triangle itself (bounding box within RASTER_SMALL_EXTENT pixels: the small-triangle
// path, as Nanite's compute rasterizer does) or stores it and reserves an entry per tile of its box,
// which the bin pass fills (Laine & Karras 2011's coarse stage, one list of (triangle, tile) entries).
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "raster/raster.glsl"
#include "render/instances.glsl"

layout(local_size_x = RASTER_SETUP_GROUP) in;

layout(set = 0, binding = 7, std430) readonly buffer Vertices { float vertexData[]; };  // penumbra::Vertex
layout(set = 0, binding = 8, std430) readonly buffer Indices { uint indices[]; };
layout(set = 0, binding = 9, std430) readonly buffer TriangleMaterials { uint triangleMaterials[]; };
layout(set = 0, binding = 10, std430) readonly buffer Layers { RasterLayer rasterLayers[]; };
layout(set = 0, binding = 11, std430) readonly buffer DrawnTriangles { uvec2 drawnTriangles[]; };  // (instance, triangle)
layout(push_constant) uniform Push { RasterPush push; };

const int kVertexFloats = 8;  // position xyz, normal xyz, uv
const int kMaxPolygon = 9;    // a triangle clipped by 6 planes
const float kGuardBand = 4.0;  // |x|, |y| <= kGuardBand * w keeps snapped coordinates far inside int32

struct ClipVertex {
    vec4 position;  // clip space
    vec2 uv;
};

ClipVertex fetch(uint index, mat4 viewProj) {
    const uint base = index * kVertexFloats;
    const vec3 p = vec3(vertexData[base], vertexData[base + 1], vertexData[base + 2]);
    return ClipVertex(viewProj * vec4(p, 1.0), vec2(vertexData[base + 6], vertexData[base + 7]));
}

// Signed distances to the clip planes: near (z >= 0), far (z <= w), then the guard band.
float planeDistance(vec4 c, int plane) {
    switch (plane) {
        case 0: return c.z;
        case 1: return c.w - c.z;
        case 2: return kGuardBand * c.w + c.x;
        case 3: return kGuardBand * c.w - c.x;
        case 4: return kGuardBand * c.w + c.y;
        default: return kGuardBand * c.w - c.y;
    }
}

uint outcode(vec4 c) {
    uint code = 0u;
    for (int p = 0; p < 6; ++p)
        if (planeDistance(c, p) < 0.0) code |= 1u << p;
    return code;
}

// Window position (x, y in pixels, z = depth) of a clip-space vertex: the viewport transform.
vec3 toWindow(vec4 c, float halfSize) {
    const vec3 ndc = c.xyz / c.w;
    return vec3(ndc.xy * halfSize + halfSize, ndc.z);
}

// Plane (value at v0, d/dx, d/dy) of a value given at three window positions.
vec4 plane(vec3 a, vec2 p0, vec2 p1, vec2 p2, float invDet) {
    const vec2 e1 = p1 - p0, e2 = p2 - p0;
    const float d1 = a.y - a.x, d2 = a.z - a.x;
    return vec4(a.x, (d1 * e2.y - d2 * e1.y) * invDet, (e1.x * d2 - e2.x * d1) * invDet, 0.0);
}

// Vulkan's depth bias for a float depth buffer: r = 2^(exponent of the largest z - 23 mantissa bits).
float depthBias(float maxZ, float slope) {
    int e;
    frexp(maxZ, e);  // maxZ = m 2^e, m in [0.5, 1): the IEEE exponent is e - 1
    const float r = maxZ > 0.0 ? ldexp(1.0, e - 24) : 0.0;
    return push.bias.x * r + push.bias.y * slope;
}

// Stores a large triangle and reserves one tile entry per tile of its box (the bin pass fills them
// in parallel: binning a layer-sized triangle here took one thread through 4096 tiles); false when
// a list is full (the caller rasterizes it). The record's origin.w holds its first entry (-1: none).
bool bin(RasterTriangle t, Edges e) {
    const uint record = atomicAdd(counters.counts.x, 1u);
    if (record >= push.capacity.x) return false;
    const ivec4 tiles = ivec4(e.bbox.xy / RASTER_TILE_SIZE, e.bbox.zw / RASTER_TILE_SIZE);
    const uint n = uint((tiles.z - tiles.x + 1) * (tiles.w - tiles.y + 1));
    const uint first = atomicAdd(counters.counts.y, n);
    const bool fits = first + n <= push.capacity.y;
    t.origin.w = fits ? float(first) : -1.0;  // capacities stay below 2^24: exact in a float
    records[record] = t;
    return fits;
}

// One triangle of the clipped polygon, in clip space.
void emitTriangle(ClipVertex c0, ClipVertex c1, ClipVertex c2, uint layer, uint material, bool singleSided,
                  bool alphaTested, uvec2 ids) {
    const int res = int(push.target.x), bits = int(push.target.y);
    const float halfSize = 0.5 * float(res), one = float(1 << bits);
    vec3 w0 = toWindow(c0.position, halfSize), w1 = toWindow(c1.position, halfSize), w2 = toWindow(c2.position, halfSize);
    ivec2 s0 = ivec2(roundEven(w0.xy * one)), s1 = ivec2(roundEven(w1.xy * one)), s2 = ivec2(roundEven(w2.xy * one));
    const int64_t area = int64_t(s1.x - s0.x) * int64_t(s2.y - s0.y) - int64_t(s1.y - s0.y) * int64_t(s2.x - s0.x);
    if (area == 0l || (area < 0l && singleSided)) return;  // empty, or a back face (fronts are clockwise)
    if (area < 0l) {  // a double-sided back face: reorder to the positive winding the edges expect
        ClipVertex ct = c1; c1 = c2; c2 = ct;
        vec3 wt = w1; w1 = w2; w2 = wt;
        ivec2 st = s1; s1 = s2; s2 = st;
    }
    const Edges e = makeEdges(s0, s1, s2, bits, res);
    if (e.bbox.x > e.bbox.z || e.bbox.y > e.bbox.w) return;
    const float det = (w1.x - w0.x) * (w2.y - w0.y) - (w2.x - w0.x) * (w1.y - w0.y);
    if (det == 0.0) return;
    const float invDet = 1.0 / det;
    RasterTriangle t;
    t.xy01 = uvec4(ivec4(s0, s1));
    t.xy2 = uvec4(uvec2(ivec2(s2)), layer, material);
    t.origin = vec4(w0.xy, alphaTested ? 1.0 : 0.0, 0.0);
    t.depth = plane(vec3(w0.z, w1.z, w2.z), w0.xy, w1.xy, w2.xy, invDet);
    t.depth.w = depthBias(max(w0.z, max(w1.z, w2.z)), max(abs(t.depth.y), abs(t.depth.z)));
    const vec3 iw = 1.0 / vec3(c0.position.w, c1.position.w, c2.position.w);
    t.invW = plane(iw, w0.xy, w1.xy, w2.xy, invDet);
    t.uOverW = plane(vec3(c0.uv.x, c1.uv.x, c2.uv.x) * iw, w0.xy, w1.xy, w2.xy, invDet);
    t.vOverW = plane(vec3(c0.uv.y, c1.uv.y, c2.uv.y) * iw, w0.xy, w1.xy, w2.xy, invDet);
    t.ids = uvec4(ids, 0u, 0u);
    const int smallExtent = int(push.capacity.z);
    const bool small = e.bbox.z - e.bbox.x < smallExtent && e.bbox.w - e.bbox.y < smallExtent;
    if (small || !bin(t, e)) {
        if (!small) atomicAdd(counters.counts.z, 1u);
        rasterizeRect(t, e, e.bbox, bits, res);
    }
}

ClipVertex lerpVertex(ClipVertex a, ClipVertex b, float t) {
    return ClipVertex(mix(a.position, b.position, t), mix(a.uv, b.uv, t));
}

// Sutherland-Hodgman against the planes in `planes`, then a fan of triangles.
void clipAndEmit(ClipVertex v[3], uint planes, uint layer, uint material, bool singleSided, bool alphaTested,
                 uvec2 ids) {
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
            if ((da >= 0.0) != (db >= 0.0) && m < kMaxPolygon) next[m++] = lerpVertex(a, b, da / (da - db));
        }
        n = m;
        for (int i = 0; i < n; ++i) poly[i] = next[i];
    }
    for (int i = 1; i + 1 < n; ++i)
        emitTriangle(poly[0], poly[i], poly[i + 1], layer, material, singleSided, alphaTested, ids);
}

void setupTriangle(uint drawn, RasterLayer target) {
    const uvec2 ref = drawnTriangles[drawn];
    const uint triangle = ref.y;
    const uint material = triangleMaterials[triangle];
    const GpuMaterial m = materials[material];
    if (m.info.y == ALPHA_BLEND && target.info.z != 0u) return;  // a deep shadow map takes it
    const mat4 viewProj = views.viewProj[target.info.x] * instances[ref.x].model;
    const bool mirrored = instances[ref.x].info.x != 0u;  // keeps the fronts' winding, as the hardware's cull flip does
    ClipVertex v[3];
    for (int i = 0; i < 3; ++i) v[i] = fetch(indices[triangle * 3 + (mirrored ? (3 - i) % 3 : i)], viewProj);
    const uint c0 = outcode(v[0].position), c1 = outcode(v[1].position), c2 = outcode(v[2].position);
    if ((c0 & c1 & c2) != 0u) return;  // entirely outside one plane
    const uint layer = target.info.y;
    const bool singleSided = m.info.z == 0u, alphaTested = m.info.y == ALPHA_MASK;
    const uvec2 ids = uvec2(drawn + 1u, target.info.w);  // the visibility ID (render/visibility.glsl)
    if ((c0 | c1 | c2) == 0u)
        emitTriangle(v[0], v[1], v[2], layer, material, singleSided, alphaTested, ids);
    else
        clipAndEmit(v, c0 | c1 | c2, layer, material, singleSided, alphaTested, ids);
}

void main() {
    const uint stride = gl_NumWorkGroups.x * RASTER_SETUP_GROUP;
    const RasterLayer target = rasterLayers[gl_GlobalInvocationID.y];
    for (uint t = gl_GlobalInvocationID.x; t < push.target.z; t += stride) setupTriangle(t, target);
}
