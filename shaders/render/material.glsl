// Material lookup shared by the fragment shaders that draw the scene.
layout(set = 0, binding = 1, std430) readonly buffer Materials { GpuMaterial materials[]; };
layout(set = 0, binding = 2) uniform sampler2DArray materialTextures;

vec4 baseColor(uint index, vec2 uv) {
    GpuMaterial m = materials[index];
    vec4 c = m.baseColor;
    if (m.info.x != NO_TEXTURE) c *= texture(materialTextures, vec3(uv, float(m.info.x)));
    return c;
}

bool alphaDiscarded(uint index, float alpha) {
    GpuMaterial m = materials[index];
    return m.info.y == ALPHA_MASK && alpha < m.params.x;
}

// With explicit uv gradients (compute resolves of visibility IDs: render/visibility.glsl).
vec4 baseColorGrad(uint index, vec2 uv, vec2 dx, vec2 dy) {
    GpuMaterial m = materials[index];
    vec4 c = m.baseColor;
    if (m.info.x != NO_TEXTURE) c *= textureGrad(materialTextures, vec3(uv, float(m.info.x)), dx, dy);
    return c;
}
