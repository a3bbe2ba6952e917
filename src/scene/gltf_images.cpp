#include "scene/gltf_images.h"

#include <algorithm>
#include <atomic>
#include <climits>
#include <thread>

#include <fmt/format.h>
#include <stb_image.h>

namespace penumbra::gltf {
namespace {

std::string describeImage(const tinygltf::Image& img, size_t index) {
    if (!img.uri.empty() && img.uri.rfind("data:", 0) != 0) return fmt::format("image {} ('{}')", index, img.uri);
    return fmt::format("image {}{}", index, img.name.empty() ? "" : " '" + img.name + "'");
}

// RGBA8 texels of one encoded image, or an error text.
std::optional<Texture> decode(const tinygltf::Image& img, std::string& error) {
    if (!img.as_is || img.image.empty()) {
        error = "its file is missing or unreadable";
        return std::nullopt;
    }
    int w = 0, h = 0, channels = 0;
    // The header's size first (gltf_images.h: kMaxTextureTexels).
    if (!stbi_info_from_memory(img.image.data(), int(img.image.size()), &w, &h, &channels)) {
        error = fmt::format("it cannot be decoded ({})", stbi_failure_reason());
        return std::nullopt;
    }
    if (w > int(kMaxTextureSize) || h > int(kMaxTextureSize) || uint64_t(w) * uint64_t(h) > kMaxTextureTexels) {
        error = fmt::format("it is {}x{}, more than the largest texture penumbra loads ({} on a side, {}x{} texels)",
                            w, h, kMaxTextureSize, 8192, 8192);
        return std::nullopt;
    }
    // The file's own channels, widened to RGBA here in one pass: asking stb for 4 costs one more
    // image-sized buffer (64 MB at 4096^2), and fresh memory is what a large texture's load spends on.
    stbi_uc* texels = stbi_load_from_memory(img.image.data(), int(img.image.size()), &w, &h, &channels, 0);
    if (!texels || channels < 1 || channels > 4) {
        error = fmt::format("it cannot be decoded ({})", texels ? "unsupported channel count" : stbi_failure_reason());
        stbi_image_free(texels);
        return std::nullopt;
    }
    Texture t;
    t.width = uint32_t(w);
    t.height = uint32_t(h);
    const size_t n = size_t(w) * size_t(h);
    t.rgba8.resize(n * 4);
    uint8_t* out = t.rgba8.data();
    for (size_t i = 0; i < n; ++i, out += 4) {
        const stbi_uc* in = texels + i * size_t(channels);
        const bool grey = channels < 3;
        out[0] = in[0];
        out[1] = grey ? in[0] : in[1];
        out[2] = grey ? in[0] : in[2];
        out[3] = channels == 2 ? in[1] : channels == 4 ? in[3] : 255;
    }
    stbi_image_free(texels);
    return t;
}

}  // namespace

bool keepEncodedImage(tinygltf::Image* image, int index, std::string* err, std::string*, int, int,
                      const unsigned char* bytes, int size, void* user) {
    // tinygltf hands over an image's bufferView without checking it against its buffer; `user` is the
    // model being loaded, whose buffers are read by then.
    if (image->bufferView >= 0 && user) {
        const auto* model = static_cast<const tinygltf::Model*>(user);
        const tinygltf::BufferView& view = model->bufferViews[size_t(image->bufferView)];
        const size_t bufferSize = model->buffers[size_t(view.buffer)].data.size();
        if (view.byteLength > bufferSize || view.byteOffset > bufferSize - view.byteLength ||
            view.byteLength > size_t(INT_MAX)) {
            if (err)
                *err += fmt::format("image {}: bufferView {} (offset {}, length {}) exceeds its buffer of {} bytes",
                                    index, image->bufferView, view.byteOffset, view.byteLength, bufferSize);
            return false;
        }
    }
    image->image.assign(bytes, bytes + std::max(size, 0));
    image->as_is = true;
    return true;
}

std::vector<std::optional<Texture>> decodeImages(const tinygltf::Model& model, const std::vector<bool>& used,
                                                 std::vector<std::string>& warnings) {
    const size_t n = model.images.size();
    std::vector<std::optional<Texture>> out(n);
    std::vector<std::string> errors(n);
    std::atomic<size_t> next{0};
    auto worker = [&] {
        for (size_t i = next++; i < n; i = next++)
            if (i < used.size() && used[i]) out[i] = decode(model.images[i], errors[i]);
    };
    const size_t wanted = size_t(std::count(used.begin(), used.end(), true));
    const size_t threads = std::min<size_t>(std::max(1u, std::thread::hardware_concurrency()), wanted);
    std::vector<std::thread> pool;
    for (size_t t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
    for (size_t i = 0; i < n; ++i)
        if (!errors[i].empty())
            warnings.push_back(fmt::format("{} is dropped: {}; its materials render untextured",
                                           describeImage(model.images[i], i), errors[i]));
    return out;
}

}  // namespace penumbra::gltf
