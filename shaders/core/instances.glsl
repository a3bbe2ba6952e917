// The scene's instance table (shared/types.h GpuInstance), read by every pass that draws meshes. A
// draw covers a run of instances of one mesh, `layers` instances each (layered shadow passes; 1
// elsewhere): instance = gl_BaseInstance + (gl_InstanceIndex - gl_BaseInstance) / layers, layer = the
// remainder.
#ifndef PENUMBRA_INSTANCES_GLSL
#define PENUMBRA_INSTANCES_GLSL
#include "core/scene_bindings.h"
layout(set = 0, binding = SCENE_INSTANCES_BINDING, std430) readonly buffer Instances { GpuInstance instances[]; };

// Macros, not functions: compute shaders include this file too, and have no instance built-ins.
#define sceneInstance(layers) (gl_BaseInstance + (gl_InstanceIndex - gl_BaseInstance) / (layers))
#define instanceLayer(layers) ((gl_InstanceIndex - gl_BaseInstance) % (layers))

vec3 instanceWorld(int instance, vec3 p) { return (instances[instance].model * vec4(p, 1.0)).xyz; }
vec3 instanceNormal(int instance, vec3 n) { return mat3(instances[instance].normal) * n; }
#endif
