// Material lookup shared by the fragment shaders that draw the scene.
#include "core/scene_bindings.h"
layout(set = 0, binding = SCENE_MATERIALS, std430) readonly buffer Materials { GpuMaterial materials[]; };
#include "core/material_textures.glsl"

vec4 baseColor(uint index, vec2 uv) {
    GpuMaterial m = materials[index];
    vec4 c = m.baseColor;
    if (m.texture != NO_TEXTURE) c *= materialTexture(m.texture, uv);
    return c;
}

bool alphaDiscarded(uint index, float alpha) {
    GpuMaterial m = materials[index];
    return m.alphaMode == ALPHA_MASK && alpha < m.alphaCutoff;
}

// With explicit uv gradients (compute resolves of visibility IDs: core/visibility.glsl).
vec4 baseColorGrad(uint index, vec2 uv, vec2 dx, vec2 dy) {
    GpuMaterial m = materials[index];
    vec4 c = m.baseColor;
    if (m.texture != NO_TEXTURE) c *= materialTextureGrad(m.texture, uv, dx, dy);
    return c;
}
