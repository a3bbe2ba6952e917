// The material textures' GPU copy: every texture its own RGBA8 sRGB image at its own size, its full
// mip chain built with blits on the GPU (filtered in linear light: the format is sRGB). No texel is
// resampled on the CPU (that took 12-27 s for one 4096^2 texture), none to a common size, and one
// texture's staging memory at a time is alive.
#pragma once
#include <cstdint>

#include "scene/scene.h"
#include "vk/commands.h"

namespace penumbra {

// Levels of a full mip chain of a width x height image (down to 1x1).
uint32_t mipLevelCount(uint32_t width, uint32_t height);
// Texel bytes of that chain in RGBA8: each level max(1, w >> l) x max(1, h >> l).
uint64_t mipChainBytes(uint32_t width, uint32_t height);

// `texture` at its own size with its mip chain, left SHADER_READ_ONLY.
vk::Image uploadTexture(vk::CommandContext& cmd, const Texture& texture, const char* name);

}  // namespace penumbra
