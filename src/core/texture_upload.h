// The material textures' GPU copy: RGBA8 sRGB images kept at the textures' own sizes, their full mip
// chains built with blits on the GPU (filtered in linear light: the format is sRGB). No texel is
// resampled on the CPU (a large texture's filtering on one core stalls loading), and one texture's staging memory
// at a time is alive.
//
// The table (core/material_textures.glsl) has MATERIAL_TEXTURE_SLOTS slots, each a 2D array: the
// textures of one size share a slot, a layer each, so any number of textures of up to that many
// sizes keep their own size. Beyond that many sizes, the textures of the rarest sizes share one last
// slot at their largest width and height (blitted up on the GPU, a warning says so).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "shared/types.h"
#include "vk/commands.h"

namespace penumbra {

// Levels of a full mip chain of a width x height image (down to 1x1).
uint32_t mipLevelCount(uint32_t width, uint32_t height);
// Texel bytes of that chain in RGBA8: each level max(1, w >> l) x max(1, h >> l).
uint64_t mipChainBytes(uint32_t width, uint32_t height);

struct TextureSlot {
    uint32_t width = 1, height = 1;
    std::vector<uint32_t> textures;  // the scene texture in each layer
};

struct TextureTablePlan {
    std::vector<TextureSlot> slots;  // at most MATERIAL_TEXTURE_SLOTS
    // Per scene texture, what GpuMaterial.texture holds: slot | layer << TEXTURE_LAYER_SHIFT.
    std::vector<uint32_t> handles;
    uint32_t resampled = 0;  // textures not at their own size (the rarest sizes beyond the slots)
    uint64_t bytes() const;  // every slot's array with its mip chain
    std::string warning() const;  // empty when every texture keeps its size
};

// Slots in order of first use; `maxLayers` per slot (256: every Vulkan device's maxImageArrayLayers).
// Throws std::invalid_argument when the textures do not fit at all.
TextureTablePlan planTextureTable(const std::vector<Texture>& textures, uint32_t slots = MATERIAL_TEXTURE_SLOTS,
                                  uint32_t maxLayers = 256);

// One slot's array with its mip chain, left SHADER_READ_ONLY: texture i of the slot in layer i, copied
// when it has the slot's size, else blitted.
vk::Image uploadTextureSlot(vk::CommandContext& cmd, const std::vector<Texture>& textures, const TextureSlot& slot,
                            const char* name);

}  // namespace penumbra
