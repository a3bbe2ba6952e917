// Base-colour textures for the reference path tracer: bilinear sampling of the sRGB-encoded RGBA8
// texels decoded to linear before filtering (what a GPU's sRGB texture unit does), repeat wrap, and
// trilinear mip-mapped lookups at camera hits, where the pixel's footprint is known.
//
// Why mip-map a ground truth: the rasterizer samples each pixel once, at its centre, with a
// mip-mapped (pre-filtered) texture. A reference that sampled full-resolution texels at the same
// points would alias VC's window textures into noise as large as the lighting error being measured
// (relative L1 of VC's direct light 0.32); filtering over the same footprint makes texture detail
// cancel out of the comparison. For the same reason the mip levels are those the renderer shades
// with: each texture at its own size, every level from the one above in linear light, as the
// renderer's blit chain builds them (core/texture_upload.cpp).
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace penumbra::reference {

// Linear RGBA at uv on one level: bilinear, texel centres at half-integers (Vulkan), repeat wrap.
glm::vec4 sampleTexture(const Texture& texture, glm::vec2 uv);

class MipChain {
public:
    // Level 0 is `base` itself (not copied).
    explicit MipChain(const Texture& base);
    // Trilinear lookup; `dUVdx`, `dUVdy`: the change of uv across one pixel. Level of detail as
    // Vulkan defines it for isotropic filtering: lambda = log2(max(|dUVdx * size|, |dUVdy * size|)).
    glm::vec4 sample(glm::vec2 uv, glm::vec2 dUVdx, glm::vec2 dUVdy) const;
    size_t levels() const { return 1 + smaller_.size(); }
    const Texture& level(size_t i) const { return i > 0 ? smaller_[i - 1] : *original_; }

private:
    const Texture* original_;
    std::vector<Texture> smaller_;  // levels 1.. : halved (rounded down, at least 1) per level
};

}  // namespace penumbra::reference
