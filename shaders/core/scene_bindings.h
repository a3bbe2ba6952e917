// Binding numbers of the scene's sets, included by the GLSL that reads the scene and by the C++ that
// declares and binds them (src/core/scene_gpu.*): each number is written here only.
// Set 0 of every pipeline that draws or fetches the scene starts with the draw set; a pass adds its
// own bindings around these. tests/spirv_reflection_test.cpp checks the compiled modules.
#ifndef PENUMBRA_SCENE_BINDINGS_H
#define PENUMBRA_SCENE_BINDINGS_H

// The draw set (SceneGpu::drawSetBindings, declareDrawSet).
#define SCENE_VIEWS 0      // mat4 per views row (0 the camera, 1.. the shadow layers)
#define SCENE_MATERIALS 1  // GpuMaterial per material
#define SCENE_INSTANCES_BINDING 15  // GpuInstance per instance ("instances")

// The drawn triangles as compute passes fetch them (SceneGpu::declareTriangles, core/triangles.glsl).
#define SCENE_VERTICES 12
#define SCENE_INDICES 13
#define SCENE_TRIANGLE_MATERIALS 14
#define SCENE_DRAWN_TRIANGLES 16

// Set 1: the material texture table (core/material_textures.glsl).
#define SCENE_TEXTURE_SET 1
#define SCENE_TEXTURES 0
#define SCENE_TEXTURE_SAMPLER 1

#endif
