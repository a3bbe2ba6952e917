// Material lookup shared by the fragment shaders that draw the scene.
layout(set = 0, binding = 1, std430) readonly buffer Materials { GpuMaterial materials[]; };
#include "core/material_textures.glsl"

vec4 baseColor(uint index, vec2 uv) {
    GpuMaterial m = materials[index];
    vec4 c = m.baseColor;
    if (m.info.x != NO_TEXTURE) c *= materialTexture(m.info.x, uv);
    return c;
}

bool alphaDiscarded(uint index, float alpha) {
    GpuMaterial m = materials[index];
    return m.info.y == ALPHA_MASK && alpha < m.params.x;
}

// With explicit uv gradients (compute resolves of visibility IDs: core/visibility.glsl).
vec4 baseColorGrad(uint index, vec2 uv, vec2 dx, vec2 dy) {
    GpuMaterial m = materials[index];
    vec4 c = m.baseColor;
    if (m.info.x != NO_TEXTURE) c *= materialTextureGrad(m.info.x, uv, dx, dy);
    return c;
}
