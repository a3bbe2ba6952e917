#include "reference/texture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace penumbra::reference {
namespace {

// sRGB decode of the 256 byte values (IEC 61966-2-1), the table a GPU's sRGB texture unit applies.
const std::array<float, 256>& srgbTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) {
            const double c = i / 255.0;
            t[i] = float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
        }
        return t;
    }();
    return table;
}

}  // namespace

glm::vec4 sampleTexture(const Texture& t, glm::vec2 uv) {
    if (t.width == 0 || t.height == 0 || t.rgba8.size() < size_t(t.width) * t.height * 4) return glm::vec4(1.0f);
    // Repeat wrap: only the fraction of uv matters (which also keeps the integer texel index small).
    uv -= glm::floor(uv);
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) uv = glm::vec2(0.0f);
    const float x = uv.x * float(t.width) - 0.5f, y = uv.y * float(t.height) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const float ax = x - fx, ay = y - fy;
    const int w = int(t.width), h = int(t.height);
    auto wrap = [](int c, int n) { return uint32_t(((c % n) + n) % n); };
    const uint32_t x0 = wrap(int(fx), w), x1 = wrap(int(fx) + 1, w);
    const uint32_t y0 = wrap(int(fy), h), y1 = wrap(int(fy) + 1, h);
    const std::array<float, 256>& lut = srgbTable();
    auto texel = [&](uint32_t tx, uint32_t ty) {
        const uint8_t* p = &t.rgba8[(size_t(ty) * t.width + tx) * 4];
        return glm::vec4(lut[p[0]], lut[p[1]], lut[p[2]], p[3] * (1.0f / 255.0f));
    };
    return glm::mix(glm::mix(texel(x0, y0), texel(x1, y0), ax), glm::mix(texel(x0, y1), texel(x1, y1), ax), ay);
}

namespace {

uint8_t encodeSrgb(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    const float e = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return uint8_t(e * 255.0f + 0.5f);
}

// Resamples `src` to w x h as the renderer's vkCmdBlitImage with VK_FILTER_LINEAR does
// (core/texture_upload.cpp): each target texel centre mapped onto the source, bilinear with
// clamped edges, in linear light (sRGB colour, linear alpha), so that both see the same texels.
Texture resample(const Texture& src, uint32_t w, uint32_t h) {
    Texture t{w, h, std::vector<uint8_t>(size_t(w) * h * 4)};
    const std::array<float, 256>& lut = srgbTable();
    const float sx = float(src.width) / float(w), sy = float(src.height) / float(h);
    auto texel = [&](int x, int y, int c) {
        x = std::clamp(x, 0, int(src.width) - 1), y = std::clamp(y, 0, int(src.height) - 1);
        const uint8_t v = src.rgba8[(size_t(y) * src.width + size_t(x)) * 4 + size_t(c)];
        return c == 3 ? v * (1.0f / 255.0f) : lut[v];
    };
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const float u = (float(x) + 0.5f) * sx - 0.5f, v = (float(y) + 0.5f) * sy - 0.5f;
            const int x0 = int(std::floor(u)), y0 = int(std::floor(v));
            const float ax = u - float(x0), ay = v - float(y0);
            for (int c = 0; c < 4; ++c) {
                const float top = texel(x0, y0, c) * (1 - ax) + texel(x0 + 1, y0, c) * ax;
                const float bottom = texel(x0, y0 + 1, c) * (1 - ax) + texel(x0 + 1, y0 + 1, c) * ax;
                const float value = top * (1 - ay) + bottom * ay;
                t.rgba8[(size_t(y) * w + x) * 4 + size_t(c)] =
                    c == 3 ? uint8_t(std::clamp(value, 0.0f, 1.0f) * 255.0f + 0.5f) : encodeSrgb(value);
            }
        }
    return t;
}

}  // namespace

MipChain::MipChain(const Texture& original) : original_(&original) {
    const size_t texels = size_t(original.width) * original.height;
    if (texels == 0 || original.rgba8.size() < texels * 4) return;
    const Texture& base = level(0);
    uint32_t w = base.width, h = base.height;
    while (w > 1 || h > 1) {
        w = std::max(1u, w / 2), h = std::max(1u, h / 2);
        // Each level from the one above, as the renderer's blit chain builds them.
        smaller_.push_back(resample(smaller_.empty() ? level(0) : smaller_.back(), w, h));
    }
}

glm::vec4 MipChain::sample(glm::vec2 uv, glm::vec2 dUVdx, glm::vec2 dUVdy) const {
    const glm::vec2 size(float(level(0).width), float(level(0).height));
    const float rho = std::max(glm::length(dUVdx * size), glm::length(dUVdy * size));
    const float lambda = std::isfinite(rho) && rho > 0.0f ? std::log2(rho) : 0.0f;
    const float lod = std::clamp(lambda, 0.0f, float(levels() - 1));
    const size_t l0 = size_t(lod);
    const size_t l1 = std::min(l0 + 1, levels() - 1);
    const float f = lod - float(l0);
    const glm::vec4 a = sampleTexture(level(l0), uv);
    return f > 0.0f ? glm::mix(a, sampleTexture(level(l1), uv), f) : a;
}

}  // namespace penumbra::reference
