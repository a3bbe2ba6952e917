// Cube face of direction d, in the order +x, -x, +y, -y, +z, -z (cubeFaceProjections): shared by the
// shadow maps' lookup (shadow/project.glsl) and the deep shadow maps' (dsm/dsm_lookup.glsl).
#ifndef SHADOW_CUBE_FACE_GLSL
#define SHADOW_CUBE_FACE_GLSL
uint cubeFace(vec3 d) {
    vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0u : 1u;
    if (a.y >= a.z) return d.y >= 0.0 ? 2u : 3u;
    return d.z >= 0.0 ? 4u : 5u;
}
#endif
