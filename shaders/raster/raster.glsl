// Coverage, depth and alpha test of one set-up triangle, shared by the setup pass (small triangles,
// rasterized by the thread that set them up) and the tile pass (large ones, one workgroup per tile).
// The rules are the hardware's (Vulkan rasterization of a D32_SFLOAT depth-only view):
//  - sample at the pixel centre; vertices snapped to subPixelPrecisionBits; edge functions exact in
//    64-bit integers; a sample on an edge is covered only by a top or left edge (top-left rule);
//  - depth = the plane of z/w through the three unsnapped window-space vertices, evaluated at the
//    sample, in the arithmetic of lavapipe's setup and interpolator (setup.comp's depthPlane);
//  - depth bias of a float depth buffer: constant * 2^(exponent(max |z|) - 23) + slope * max(|dz/dx|,
//    |dz/dy|), then clamped to [0, 1];
//  - alpha-masked casters sample the base-colour alpha (perspective-correct uv, analytic gradients
//    for the texture LOD) and drop samples below the material's cutoff.
// The depth test is a 32-bit atomicMin on the float bits: depths in [0, 1] order like their bits.
// Layers with visibility IDs (an RSM's) test a 64-bit atomicMin of depth bits << 32 | ID instead, so
// depth and ID of the nearest triangle land together (ties: the smaller ID).
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require

// Set 0 starts like the scene's draw set (render/scene_gpu.h): views, materials; set 1: the textures.
#include "core/scene_bindings.h"
#include "raster/bindings.h"
layout(set = 0, binding = SCENE_VIEWS, std430) readonly buffer Views { mat4 viewProj[]; } views;
layout(set = 0, binding = SCENE_MATERIALS, std430) readonly buffer Materials { GpuMaterial materials[]; };
#include "core/material_textures.glsl"
layout(set = 0, binding = RASTER_SET_DEPTH, std430) buffer Depth { uint depthBits[]; };
layout(set = 0, binding = RASTER_SET_RECORDS, std430) buffer Records { RasterTriangle records[]; };
layout(set = 0, binding = RASTER_SET_TILE_ENTRIES, std430) buffer TileEntries { uvec2 tileEntries[]; };
// After the binning counts, the work counters (ComputeRaster::Work): work.x = the most pixels a setup
// thread tested for one triangle, y = (triangle, layer) pairs queued for the overflow pass, z = the most
// pixels an overflow thread tested for one triangle, w = the largest box (tiles) in the huge queue;
// queues.x, y = the pairs in the medium and the huge queue (raster/overflow.comp).
layout(set = 0, binding = RASTER_SET_COUNTERS, std430) buffer Counters { RasterCounters counters; uvec4 work; uvec4 queues; };
layout(set = 0, binding = RASTER_SET_DEPTH_IDS, std430) buffer DepthIds { uint64_t depthIds[]; };  // per texel of the ID layers
// Per tile of every target layer (layer-major, rows of tiles): the bin pass counts its triangles
// (count), the place pass puts its list in the list buffer (offset), the scatter pass fills the
// tile's list (cursor: its fill so far). Lists hold record indices (raster/tiles.comp).
// w: RASTER_TILE_TOUCHED where a setup thread drew into the tile (else its depth is the cleared value).
layout(set = 0, binding = RASTER_SET_TILE_BINS, std430) buffer TileBins { uvec4 tileBins[]; };  // x count, y offset, z cursor
layout(set = 0, binding = RASTER_SET_TILE_LISTS, std430) buffer TileLists { uint tileLists[]; };

uint tilesAcross(ivec2 size) { return uint((size.x + RASTER_TILE_SIZE - 1) / RASTER_TILE_SIZE); }
uint tilesDown(ivec2 size) { return uint((size.y + RASTER_TILE_SIZE - 1) / RASTER_TILE_SIZE); }
uint tileIndex(uint layer, ivec2 tile, ivec2 size) {
    return (layer * tilesDown(size) + uint(tile.y)) * tilesAcross(size) + uint(tile.x);
}

#include "raster/overflow_limits.glsl"

// Edge functions of a triangle with positive area: E_i(p) = d_i x (p - a_i) > 0 inside.
struct Edges {
    i64vec2 a[3];     // start vertex of each edge (subpixel units)
    i64vec2 d[3];     // edge vector
    int64_t bias[3];  // 0 on top and left edges (a sample on them is covered), -1 on the others
    ivec4 bbox;       // covered pixel range, inclusive: x0, y0, x1, y1 (clamped to the target)
};

// Top edge: horizontal, going right; left edge: going up (y down in window space, positive area =
// clockwise on screen). Samples exactly on any other edge belong to the neighbouring triangle.
// (32-bit compares: the edge vectors fit, and lavapipe mis-selects on some 64-bit compares.)
int64_t edgeBias(ivec2 d) {
    const bool topLeft = (d.y == 0 && d.x > 0) || d.y < 0;
    return int64_t(topLeft ? 0 : -1);
}

Edges makeEdges(ivec2 v0, ivec2 v1, ivec2 v2, int subpixelBits, ivec2 size) {
    Edges e;
    e.a[0] = i64vec2(v0); e.a[1] = i64vec2(v1); e.a[2] = i64vec2(v2);
    e.d[0] = i64vec2(v1 - v0); e.d[1] = i64vec2(v2 - v1); e.d[2] = i64vec2(v0 - v2);
    e.bias[0] = edgeBias(v1 - v0); e.bias[1] = edgeBias(v2 - v1); e.bias[2] = edgeBias(v0 - v2);
    // Pixels whose centre (p + 0.5) lies in [min, max]: ceil((min - half) / one) .. floor((max - half) / one).
    const int one = 1 << subpixelBits, centre = one >> 1;
    const ivec2 lo = min(v0, min(v1, v2)), hi = max(v0, max(v1, v2));
    const ivec2 first = (lo - centre + (one - 1)) >> subpixelBits;  // arithmetic shift: floor division
    const ivec2 last = (hi - centre) >> subpixelBits;
    e.bbox = ivec4(max(first, ivec2(0)), min(last, size - 1));
    return e;
}

// Whether the centre of pixel p is covered (64-bit: snapped coordinates reach 2^23 subpixels).
bool covers(Edges e, ivec2 p, int subpixelBits) {
    const i64vec2 s = i64vec2((p << subpixelBits) + (1 << (subpixelBits - 1)));
    for (int i = 0; i < 3; ++i) {
        const i64vec2 q = s - e.a[i];
        if (e.d[i].x * q.y - e.d[i].y * q.x + e.bias[i] < 0l) return false;
    }
    return true;
}

Edges edgesOf(RasterTriangle t, int subpixelBits, ivec2 size) {
    return makeEdges(t.vertex0, t.vertex1, t.vertex2, subpixelBits, size);
}

// Tiles: all tiles of the triangle's box that no edge excludes (an edge excludes a tile when it is
// negative at the centres of the tile's four corner pixels: the edge function is linear).
bool tileMayCover(Edges e, ivec4 rect, int bits) {
    const ivec2 corners[4] = ivec2[4](rect.xy, rect.zy, rect.xw, rect.zw);
    for (int i = 0; i < 3; ++i) {
        bool inside = false;
        for (int c = 0; c < 4; ++c) {
            const i64vec2 q = i64vec2((corners[c] << bits) + (1 << (bits - 1))) - e.a[i];
            inside = inside || e.d[i].x * q.y - e.d[i].y * q.x + e.bias[i] >= 0l;
        }
        if (!inside) return false;
    }
    return true;
}

ivec4 tileRect(ivec2 tile, ivec4 bbox) {
    const ivec2 lo = tile * RASTER_TILE_SIZE;
    return ivec4(max(lo, bbox.xy), min(lo + RASTER_TILE_SIZE - 1, bbox.zw));
}

float planeAt(vec3 plane, vec2 offset) { return plane.x + plane.y * offset.x + plane.z * offset.y; }

// Alpha test of a masked caster at window position w (perspective-correct uv; the LOD from the
// analytic uv gradients, which a 2x2 quad's differences equal on orthographic views).
bool alphaDiscarded(RasterTriangle t, vec2 offset) {
    const GpuMaterial m = materials[t.material];
    const float iw = planeAt(t.invW, offset);
    const vec2 uvw = vec2(planeAt(t.uOverW, offset), planeAt(t.vOverW, offset));
    const vec2 uv = uvw / iw;
    float alpha = m.baseColor.a;
    if (m.texture != NO_TEXTURE) {
        // d(uvw / iw) = (d uvw - uv d iw) / iw
        const vec2 dx = (vec2(t.uOverW.y, t.vOverW.y) - uv * t.invW.y) / iw;
        const vec2 dy = (vec2(t.uOverW.z, t.vOverW.z) - uv * t.invW.z) / iw;
        alpha *= materialTextureGrad(m.texture, uv, dx, dy).a;
    }
    return alpha < m.alphaCutoff;
}

// Depth test and write of one covered sample. Depth as lavapipe's interpolator takes it (setup.comp's
// depthPlane): the plane's value at the pixel's integer coordinates, two fused multiply-adds, then the bias.
uint sampleDepthBits(RasterTriangle t, ivec2 p) {
    const vec2 xy = vec2(p);
    precise const float z =
        clamp(fma(t.depthPlane.z, xy.y, fma(t.depthPlane.y, xy.x, t.depthPlane.x)) + t.depthBias, 0.0, 1.0);
    return floatBitsToUint(z) & 0x7FFFFFFFu;  // -0 -> +0
}

void shadeSample(RasterTriangle t, ivec2 p, ivec2 size) {
    const vec2 xy = vec2(p);
    const uint bits = sampleDepthBits(t, p);
    if (t.idLayerPlusOne != 0u) {
        const uint index = ((t.idLayerPlusOne - 1u) * uint(size.y) + uint(p.y)) * uint(size.x) + uint(p.x);
        if (bits >= uint(depthIds[index] >> 32)) return;  // cleared above 1.0: the far plane writes too
        if (t.alphaTested != 0u && alphaDiscarded(t, xy + 0.5 - t.origin)) return;
        atomicMin(depthIds[index], uint64_t(bits) << 32 | uint64_t(t.visibilityId));
        return;
    }
    const uint index = (t.layer * uint(size.y) + uint(p.y)) * uint(size.x) + uint(p.x);
    if (bits >= depthBits[index]) return;  // cheap early reject before the atomic and the texture
    if (t.alphaTested != 0u && alphaDiscarded(t, xy + 0.5 - t.origin)) return;
    atomicMin(depthBits[index], bits);
}

// Every covered sample of a small triangle, in 32-bit edge functions stepped along each row (the
// setup pass's small triangles: 64-bit products per sample cost several instructions each). With
// |d_i| < 2^13 subpixels (smallEnough) and q within the triangle's box, |E| < 2^27: exact, as the
// 64-bit evaluation (covers) is.
void rasterizeSmall(RasterTriangle t, Edges e, int subpixelBits, ivec2 size) {
    const int one = 1 << subpixelBits, centre = one >> 1;
    ivec3 rowStart, stepX, stepY, bias;
    for (int i = 0; i < 3; ++i) {
        const ivec2 d = ivec2(e.d[i]), q = (e.bbox.xy << subpixelBits) + centre - ivec2(e.a[i]);
        rowStart[i] = d.x * q.y - d.y * q.x;
        stepX[i] = -d.y * one;
        stepY[i] = d.x * one;
        bias[i] = int(e.bias[i]);
    }
    for (int y = e.bbox.y; y <= e.bbox.w; ++y, rowStart += stepY) {
        ivec3 edge = rowStart + bias;
        for (int x = e.bbox.x; x <= e.bbox.z; ++x, edge += stepX)
            if (all(greaterThanEqual(edge, ivec3(0)))) shadeSample(t, ivec2(x, y), size);
    }
}

// Whether rasterizeSmall's 32-bit arithmetic holds for `e` (vertices within 2^13 subpixels of one
// another on both axes).
bool smallEnough(Edges e) {
    for (int i = 0; i < 3; ++i)
        if (abs(e.d[i].x) >= 8192l || abs(e.d[i].y) >= 8192l) return false;
    return true;
}

// Every covered sample of `t` inside the pixel rectangle r (inclusive).
void rasterizeRect(RasterTriangle t, Edges e, ivec4 r, int subpixelBits, ivec2 size) {
    for (int y = r.y; y <= r.w; ++y)
        for (int x = r.x; x <= r.z; ++x)
            if (covers(e, ivec2(x, y), subpixelBits)) shadeSample(t, ivec2(x, y), size);
}
