// Cascaded volume addressing (layouts in shared/types.h, LPV section). Needs `pc` (LpvPush).
uint cellsPerVolume() { return pc.resolution * pc.resolution * pc.resolution; }

bool insideGrid(ivec3 c) { return all(greaterThanEqual(c, ivec3(0))) && all(lessThan(c, ivec3(pc.resolution))); }

uint cellIndex(ivec3 c) { return (uint(c.z) * pc.resolution + uint(c.y)) * pc.resolution + uint(c.x); }

uint lightIndex(uint cascade, uint channel, ivec3 c) {
    return (cascade * 3u + channel) * cellsPerVolume() + cellIndex(c);
}

uint geometryIndex(uint cascade, ivec3 c) { return cascade * cellsPerVolume() + cellIndex(c); }

// Position in cell units of cascade k (cell i spans [i, i + 1); its centre is at i + 0.5).
vec3 gridCoord(GpuLpvCascade cascade, vec3 x) { return (x - cascade.origin) / cascade.cellSize; }
vec3 gridCoord(uint k, vec3 x) { return gridCoord(pc.cascades[k], x); }

// During injection (lpv.h) the fixed-point sums (lpv/fixed_point.glsl) take buffers that are free
// until the first propagation step: the light's (4 int64 per colour and cell, at 4 x lightIndex) the
// sum buffer, the geometry's (4 int64 per cell, at 4 x geometryIndex) light volume B, followed there
// by the light's scales (one uint per colour and cell, at lightRangeIndex).
uint lightRangeIndex(uint cascade, uint channel, ivec3 c) {
    return 8u * pc.cascadeCount * cellsPerVolume() + lightIndex(cascade, channel, c);
}
