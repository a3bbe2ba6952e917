// The scene's base-colour textures (SceneGpu's texture table, set 1): every texture its own image at
// its own size with its own mip chain, MATERIAL_TEXTURE_SLOTS slots (unused ones hold a 1x1 white
// texture), one shared sampler (linear, mip-mapped, repeat).
// Why a switch with constant indices: Mesa 22.3's lavapipe (Debian 12) offers no descriptor indexing
// and not even shaderSampledImageArrayDynamicIndexing, so an image array may only be indexed by a
// constant; each case below is one. It is legal for any index, uniform or not (compute resolves
// meet several materials per subgroup), on every device.
#if MATERIAL_TEXTURE_SLOTS != 28
#error "the cases below name slots 0-27: keep them in step with MATERIAL_TEXTURE_SLOTS"
#endif
layout(set = 1, binding = 0) uniform texture2D materialTextures[MATERIAL_TEXTURE_SLOTS];
layout(set = 1, binding = 1) uniform sampler materialSampler;

#define MT_CASES4(L, i) L(i) L(i + 1) L(i + 2) L(i + 3)
#define MT_CASES8(L, i) MT_CASES4(L, i) MT_CASES4(L, i + 4)
#define MT_CASES16(L, i) MT_CASES8(L, i) MT_CASES8(L, i + 8)
#define MT_SWITCH(t, L) \
    switch (int(t)) { MT_CASES16(L, 0) MT_CASES8(L, 16) MT_CASES4(L, 24) }

// Texture `t` with implicit derivatives (fragment shaders; `t` is the draw's, uniform over the draw).
vec4 materialTexture(uint t, vec2 uv) {
#define MT_IMPLICIT(i) case i: return texture(sampler2D(materialTextures[i], materialSampler), uv);
    MT_SWITCH(t, MT_IMPLICIT)
    return vec4(1.0);
}

// Texture `t` with explicit uv gradients (compute resolves and the compute rasterizer).
vec4 materialTextureGrad(uint t, vec2 uv, vec2 dx, vec2 dy) {
#define MT_GRAD(i) case i: return textureGrad(sampler2D(materialTextures[i], materialSampler), uv, dx, dy);
    MT_SWITCH(t, MT_GRAD)
    return vec4(1.0);
}
