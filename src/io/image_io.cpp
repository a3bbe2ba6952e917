#include "io/image_io.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include <stb_image_write.h>
#include <tinyexr.h>

#include "io/file_write.h"
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
    // Encoded in memory and written through writeFileChecked: stb's own file writer ignores the
    // result of fwrite and fclose, so a full disk went unnoticed.
    std::string png;
    const auto append = [](void* out, void* data, int size) {
        static_cast<std::string*>(out)->append(static_cast<const char*>(data), size_t(size));
    };
    if (!stbi_write_png_to_func(append, &png, int(width), int(height), 4, rgba8.data(), int(width * 4)))
        throw std::runtime_error("cannot encode PNG file: " + path);
    writeFileChecked(path, png);
}

void writeExr(const std::string& path, uint32_t width, uint32_t height, const std::vector<float>& rgba32f) {
    // Alpha carries no information here: RGB as 32-bit float planes in the B, G, R order EXR viewers
    // expect, uncompressed below 16x16 and ZIP above, as tinyexr's SaveEXR writes them. Encoded in
    // memory and written through writeFileChecked (SaveEXR does not check fclose).
    const size_t pixels = size_t(width) * height;
    std::vector<float> planes[3];
    for (int c = 0; c < 3; ++c) {
        planes[c].resize(pixels);
        for (size_t i = 0; i < pixels; ++i) planes[c][i] = rgba32f[i * 4 + size_t(c)];
    }
    float* planeOrder[3] = {planes[2].data(), planes[1].data(), planes[0].data()};
    EXRImage image;
    InitEXRImage(&image);
    image.num_channels = 3;
    image.images = reinterpret_cast<unsigned char**>(planeOrder);
    image.width = int(width);
    image.height = int(height);
    EXRHeader header;
    InitEXRHeader(&header);
    header.compression_type = width < 16 && height < 16 ? TINYEXR_COMPRESSIONTYPE_NONE : TINYEXR_COMPRESSIONTYPE_ZIP;
    header.num_channels = 3;
    EXRChannelInfo channels[3] = {};
    int pixelTypes[3] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT};
    int requestedTypes[3] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT};
    for (int c = 0; c < 3; ++c) channels[c].name[0] = "BGR"[c];
    header.channels = channels;
    header.pixel_types = pixelTypes;
    header.requested_pixel_types = requestedTypes;
    unsigned char* encoded = nullptr;
    const char* err = nullptr;
    const size_t size = SaveEXRImageToMemory(&image, &header, &encoded, &err);
    if (size == 0 || !encoded) {
        std::string msg = "cannot encode EXR file: " + path + (err ? " (" + oneLine(err) + ")" : "");
        if (err) FreeEXRErrorMessage(err);
        std::free(encoded);
        throw std::runtime_error(msg);
    }
    const std::string bytes(reinterpret_cast<const char*>(encoded), size);
    std::free(encoded);
    writeFileChecked(path, bytes);
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
