// The scene's base-colour textures (SceneGpu's texture table, set 1): MATERIAL_TEXTURE_SLOTS slots, each
// a 2D array of the textures of one size with their mip chains (unused slots hold a 1x1 white one),
// one shared sampler (linear, mip-mapped, repeat). A material's handle `t` names slot and layer
// (TEXTURE_LAYER_SHIFT; core/texture_upload.h plans them).
// Why a switch with constant indices: Mesa 22.3's lavapipe (Debian 12) offers no descriptor indexing
// and not even shaderSampledImageArrayDynamicIndexing, so an image array may only be indexed by a
// constant; each case below is one. It is legal for any index, uniform or not (compute resolves
// meet several materials per subgroup), on every device.
#if MATERIAL_TEXTURE_SLOTS != 28
#error "the cases below name slots 0-27: keep them in step with MATERIAL_TEXTURE_SLOTS"
#endif
#include "core/scene_bindings.h"
layout(set = SCENE_TEXTURE_SET, binding = SCENE_TEXTURES) uniform texture2DArray materialTextures[MATERIAL_TEXTURE_SLOTS];
layout(set = SCENE_TEXTURE_SET, binding = SCENE_TEXTURE_SAMPLER) uniform sampler materialSampler;

#define MT_CASES4(L, i) L(i) L(i + 1) L(i + 2) L(i + 3)
#define MT_CASES8(L, i) MT_CASES4(L, i) MT_CASES4(L, i + 4)
#define MT_CASES16(L, i) MT_CASES8(L, i) MT_CASES8(L, i + 8)
#define MT_SWITCH(t, L) \
    switch (int(t & TEXTURE_SLOT_MASK)) { MT_CASES16(L, 0) MT_CASES8(L, 16) MT_CASES4(L, 24) }
#define MT_COORD(t, uv) vec3(uv, float(t >> TEXTURE_LAYER_SHIFT))

// Texture `t` with implicit derivatives (fragment shaders; `t` is the draw's, uniform over the draw).
vec4 materialTexture(uint t, vec2 uv) {
#define MT_IMPLICIT(i) case i: return texture(sampler2DArray(materialTextures[i], materialSampler), MT_COORD(t, uv));
    MT_SWITCH(t, MT_IMPLICIT)
    return vec4(1.0);
}

// Texture `t` with explicit uv gradients (compute resolves and the compute rasterizer).
vec4 materialTextureGrad(uint t, vec2 uv, vec2 dx, vec2 dy) {
#define MT_GRAD(i) case i: return textureGrad(sampler2DArray(materialTextures[i], materialSampler), MT_COORD(t, uv), dx, dy);
    MT_SWITCH(t, MT_GRAD)
    return vec4(1.0);
}
