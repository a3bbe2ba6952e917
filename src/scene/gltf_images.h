// Image decoding for the glTF loader: tinygltf hands over each image's encoded bytes untouched
// (keepEncodedImage, its image-loader callback), and decodeImages decodes only the images that
// materials use, in parallel (a 4096^2 PNG takes about a second to decode on one core).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "scene/scene.h"

namespace penumbra::gltf {

// Images larger on a side (the renderer's largest image, renderer.cpp) or with more texels (256 MiB
// of RGBA8, 341 MiB with its mips on the device) are dropped from their header, before decoding: a
// few hundred bytes of PNG can claim a gigabyte of texels.
constexpr uint32_t kMaxTextureSize = 16384;
constexpr uint64_t kMaxTextureTexels = uint64_t(8192) * 8192;

// tinygltf LoadImageDataFunction: stores the encoded bytes in Image::image with Image::as_is set.
// `user` is the tinygltf::Model being loaded: an image's bufferView must lie inside its buffer.
bool keepEncodedImage(tinygltf::Image* image, int index, std::string* err, std::string* warn, int reqWidth,
                      int reqHeight, const unsigned char* bytes, int size, void* user);

// Per glTF image: its RGBA8 texels where `used[i]` and it decodes; nullopt otherwise, with one line in
// `warnings` for each used image that is missing or cannot be decoded (it renders untextured).
std::vector<std::optional<Texture>> decodeImages(const tinygltf::Model& model, const std::vector<bool>& used,
                                                 std::vector<std::string>& warnings);

}  // namespace penumbra::gltf
