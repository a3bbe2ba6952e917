// A VPL's light as lpv/inject.comp adds it and lpv/inject_range.comp bounds it: a VPL of flux phi is
// a Lambertian emitter of intensity phi / pi * max(0, n.w), i.e. SH coefficients phi / pi *
// CosineLobe(n), placed at x + 0.5 cell * n (half a cell along the normal, against
// self-illumination) and shared among the 8 cells around that point with trilinear weights. The
// weights move the light continuously with the VPL: given whole to the cell holding the point, a
// VPL that slid across a cell border (an RSM's texels slide over the scene as the light turns) moved
// all its light at once, and the indirect light flickered. Needs lpv/sh.glsl and lpv/volume.glsl.
const float VPL_PI = 3.14159265358979;

struct Splat {
    ivec3 base;  // the lowest of the 8 cells
    vec3 f;      // where the point lies between the centres of base and base + 1
};

// The weights come from the point's place on the world lattice of the cascade's cells, not from
// its place in the grid: a grid that moved by whole cells (nested around a moving eye) gives a VPL
// the same weight bits in the same world cells. A grid's origin within 1e-3 cell of that lattice
// (a snapped one, but for rounding) counts as on it.
Splat vplSplat(GpuVpl v, uint k) {
    const float cell = pc.cascades[k].cellSize;
    const vec3 origin = pc.cascades[k].origin / cell, whole = round(origin);
    const vec3 phase = mix(origin - whole, vec3(0.0), lessThan(abs(origin - whole), vec3(1e-3)));
    const vec3 g = (v.position + 0.5 * cell * v.normal) / cell - 0.5 - phase;
    Splat s;
    s.f = g - floor(g);
    s.base = ivec3(floor(g)) - ivec3(whole);
    return s;
}

// Corner i (0..7) of the splat: its cell and weight.
ivec3 splatCell(Splat s, uint i) { return s.base + ivec3(i & 1u, (i >> 1) & 1u, i >> 2); }
float splatWeight(Splat s, uint i) {
    const vec3 w = mix(1.0 - s.f, s.f, vec3(i & 1u, (i >> 1) & 1u, i >> 2));
    return w.x * w.y * w.z;
}

vec4 vplLight(GpuVpl v, uint channel) { return cosineLobe(v.normal) * (v.flux[channel] / VPL_PI); }

float largestMagnitude(vec4 v) { return max(max(abs(v.x), abs(v.y)), max(abs(v.z), abs(v.w))); }
