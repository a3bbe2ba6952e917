// Shared by the DSM build, resolve, link and lookup shaders (include after shared/types.h).

// Node and receiver depth: the distance from a spot or point light (viewer.w = 1), or the depth along
// a directional light (viewer.xyz = unit direction towards it). Linear in world units, so that depth
// biases are texel sizes and neighbour texels compare meaningfully.
float dsmDepth(vec4 viewer, vec3 p) {
    return viewer.w > 0.5 ? distance(p, viewer.xyz) : -dot(p, viewer.xyz);
}
