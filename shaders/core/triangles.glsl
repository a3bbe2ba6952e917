// The drawn triangles as compute passes fetch them: every instance's triangles, (instance, triangle
// in the index buffer), in world space (the instance's transform applied). Bindings SCENE_VERTICES.. of
// set 0 (SceneGpu::declareTriangles) and the instance table.
#ifndef PENUMBRA_TRIANGLES_GLSL
#define PENUMBRA_TRIANGLES_GLSL
#include "core/instances.glsl"
layout(set = 0, binding = SCENE_VERTICES, std430) readonly buffer VisVertices { float visVertex[]; };  // penumbra::Vertex
layout(set = 0, binding = SCENE_INDICES, std430) readonly buffer VisIndices { uint visIndex[]; };
layout(set = 0, binding = SCENE_TRIANGLE_MATERIALS, std430) readonly buffer VisTriangleMaterials { uint visTriangleMaterial[]; };
layout(set = 0, binding = SCENE_DRAWN_TRIANGLES, std430) readonly buffer VisDrawnTriangles { uvec2 visDrawn[]; };  // (instance, triangle)

struct VisTriangle {
    vec3 p[3];   // world space
    vec3 n[3];
    vec2 uv[3];
    uint material;
};

// Triangle `id` (non-zero) in world space.
VisTriangle fetchTriangle(uint id) {
    const uvec2 drawn = visDrawn[id - 1u];
    const int instance = int(drawn.x);
    const uint t = drawn.y;
    VisTriangle tri;
    for (int k = 0; k < 3; ++k) {
        const uint v = visIndex[t * 3u + uint(k)] * 8u;  // 8 floats per vertex
        tri.p[k] = instanceWorld(instance, vec3(visVertex[v], visVertex[v + 1u], visVertex[v + 2u]));
        tri.n[k] = instanceNormal(instance, vec3(visVertex[v + 3u], visVertex[v + 4u], visVertex[v + 5u]));
        tri.uv[k] = vec2(visVertex[v + 6u], visVertex[v + 7u]);
    }
    tri.material = visTriangleMaterial[t];
    return tri;
}
#endif
