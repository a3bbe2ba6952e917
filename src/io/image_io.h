// PNG (8-bit sRGB, tone-mapped) and EXR (linear float) files.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace penumbra {

struct ImageF {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;  // 4 floats per pixel, top row first
};

// Both throw std::runtime_error with one clear line on failure.
void writePng(const std::string& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba8);
void writeExr(const std::string& path, uint32_t width, uint32_t height, const std::vector<float>& rgba32f);
ImageF readExr(const std::string& path);

// Lower-cased extension with the dot (".png"), "" if none.
std::string fileExtension(const std::string& path);

}  // namespace penumbra
