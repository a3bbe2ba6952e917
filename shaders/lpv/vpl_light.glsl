// A VPL's light as lpv/inject.comp adds it and lpv/inject_range.comp bounds it: a VPL of flux phi is
// a Lambertian emitter of intensity phi / pi * max(0, n.w), i.e. SH coefficients phi / pi *
// CosineLobe(n), added to the cell of x + 0.5 cell * n (half a cell along the normal, against
// self-illumination). Needs lpv/sh.glsl and lpv/volume.glsl.
const float VPL_PI = 3.14159265358979;

ivec3 vplLightCell(GpuVpl v, uint k) {
    return ivec3(floor(gridCoord(k, v.position.xyz + 0.5 * pc.cascades[k].origin.w * v.normal.xyz)));
}

vec4 vplLight(GpuVpl v, uint channel) { return cosineLobe(v.normal.xyz) * (v.flux[channel] / VPL_PI); }

float largestMagnitude(vec4 v) { return max(max(abs(v.x), abs(v.y)), max(abs(v.z), abs(v.w))); }
