#include "io/image_io.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include <stb_image_write.h>
#include <tinyexr.h>

#include "io/one_line.h"

namespace penumbra {

std::string fileExtension(const std::string& path) {
    const size_t dot = path.find_last_of('.');
    const size_t slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string ext = path.substr(dot);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

void writePng(const std::string& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba8) {
    if (!stbi_write_png(path.c_str(), int(width), int(height), 4, rgba8.data(), int(width * 4)))
        throw std::runtime_error("cannot write PNG file: " + path);
}

void writeExr(const std::string& path, uint32_t width, uint32_t height, const std::vector<float>& rgba32f) {
    // Alpha carries no information here: store RGB as 32-bit float.
    std::vector<float> rgb(size_t(width) * height * 3);
    for (size_t i = 0; i < size_t(width) * height; ++i)
        for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = rgba32f[i * 4 + c];
    const char* err = nullptr;
    if (SaveEXR(rgb.data(), int(width), int(height), 3, 0, path.c_str(), &err) != TINYEXR_SUCCESS) {
        std::string msg = "cannot write EXR file: " + path + (err ? " (" + oneLine(err) + ")" : "");
        if (err) FreeEXRErrorMessage(err);
        throw std::runtime_error(msg);
    }
}

ImageF readExr(const std::string& path) {
    float* data = nullptr;
    int w = 0, h = 0;
    const char* err = nullptr;
    if (LoadEXR(&data, &w, &h, path.c_str(), &err) != TINYEXR_SUCCESS) {
        std::string msg = "cannot read EXR file: " + path + (err ? " (" + oneLine(err) + ")" : "");
        if (err) FreeEXRErrorMessage(err);
        throw std::runtime_error(msg);
    }
    ImageF img{uint32_t(w), uint32_t(h), std::vector<float>(data, data + size_t(w) * h * 4)};
    std::free(data);
    return img;
}

}  // namespace penumbra
