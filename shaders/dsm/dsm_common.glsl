// Shared by the DSM build, resolve, link and lookup shaders (include after shared/types.h).

// Node and receiver depth: the distance from a spot or point light (viewer.w = 1), or the depth along
// a directional light (viewer.xyz = unit direction towards it). Linear in world units, so that depth
// biases are texel sizes and neighbour texels compare meaningfully.
float dsmDepth(vec3 viewer, uint viewerIsPoint, vec3 p) {
    return viewerIsPoint != 0u ? distance(p, viewer) : -dot(p, viewer);
}

// Depths as uints that keep their order (negative ones too), for atomicMin (deep opacity maps).
uint orderedDepth(float d) {
    uint u = floatBitsToUint(d);
    return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}
float fromOrderedDepth(uint u) { return uintBitsToFloat((u & 0x80000000u) != 0u ? u & 0x7FFFFFFFu : ~u); }
