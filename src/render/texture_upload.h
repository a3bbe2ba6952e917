// The material textures' GPU copy: every texture uploaded at its own size and blitted (filtered in
// linear light: the format is sRGB) into its square layer of one array, whose mip chain is then
// built with blits on the GPU. No texel is resampled on the CPU (that took 12-27 s for one 4096^2
// texture), and one texture's staging memory at a time is alive.
#pragma once
#include <vector>

#include "scene/scene.h"
#include "vk/commands.h"

namespace penumbra {

// A `size` x `size` RGBA8 sRGB array with one layer per texture (one white layer when there is
// none) and a full mip chain, left SHADER_READ_ONLY.
vk::Image uploadTextureArray(vk::CommandContext& cmd, const std::vector<Texture>& textures, uint32_t size);

}  // namespace penumbra
