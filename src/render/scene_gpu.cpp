#include "render/scene_gpu.h"

#include <algorithm>

#include <stb_image_resize.h>

namespace penumbra {
namespace {

uint32_t mipCount(uint32_t size) {
    uint32_t n = 1;
    while (size > 1) size /= 2, ++n;
    return n;
}

}  // namespace

SceneGpu::SceneGpu(vk::CommandContext& cmd, const Scene& scene)
    : scene_(scene), ctx_(cmd.allocator().context()) {
    if (scene.indices.empty() && scene.strands.empty()) throw vk::VulkanError("scene has no triangles");
    // A hair-only scene (glTF lines) still binds a vertex and an index buffer: one unused element each.
    const Vertex noVertex{};
    const uint32_t noIndex = 0;
    const bool none = scene.indices.empty();
    vertices_ = cmd.createDeviceBuffer(none ? &noVertex : scene.vertices.data(),
                                       none ? sizeof(Vertex) : scene.vertices.size() * sizeof(Vertex),
                                       VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                       "vertices");
    indices_ = cmd.createDeviceBuffer(none ? &noIndex : scene.indices.data(),
                                      none ? sizeof(uint32_t) : scene.indices.size() * sizeof(uint32_t),
                                      VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                      "indices");
    std::vector<gpu::GpuMaterial> mats;
    for (const Material& m : scene.materials) {
        gpu::GpuMaterial g{};
        g.baseColor = m.baseColor;
        const bool hasTexture = m.baseColorTexture >= 0 && size_t(m.baseColorTexture) < scene.textures.size();
        g.info = {hasTexture ? uint32_t(m.baseColorTexture) : NO_TEXTURE, uint32_t(m.alphaMode),
                  m.doubleSided ? 1u : 0u, 0u};
        g.params = {m.alphaCutoff, 0, 0, 0};
        mats.push_back(g);
    }
    materials_ = cmd.createDeviceBuffer(mats.data(), mats.size() * sizeof(gpu::GpuMaterial),
                                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "materials");
    std::vector<uint32_t> triangleMaterials(std::max<size_t>(scene.indices.size() / 3, 1), 0u);
    for (const Draw& d : scene.draws)
        std::fill_n(triangleMaterials.begin() + d.firstIndex / 3, d.indexCount / 3, d.material);
    triangleMaterials_ = cmd.createDeviceBuffer(triangleMaterials.data(), triangleMaterials.size() * sizeof(uint32_t),
                                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "triangle-materials");
    uploadTextures(cmd);
}

std::vector<VkVertexInputAttributeDescription> SceneGpu::vertexAttributes() {
    return {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
            {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, normal)},
            {2, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(Vertex, uv)}};
}

std::vector<vk::Binding> SceneGpu::drawSetBindings() {
    return {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
            {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
            {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER}};
}

void SceneGpu::declareDrawSet(PassBuilder& pass, BufferHandle views) {
    FrameGraph& g = pass.graph();
    pass.storageBuffer(0, views).storageBuffer(1, g.import(materials_)).sampled(2, g.import(textures_),
                                                                                sampler_.handle());
}

void SceneGpu::uploadTextures(vk::CommandContext& cmd) {
    // Every texture is resampled (in linear light) to a square layer with a full CPU-built mip chain.
    const std::vector<Texture>& src = scene_.textures;
    const uint32_t size = src.empty() ? 1 : textureLayerSize(src);
    const uint32_t levels = mipCount(size);
    const uint32_t layers = std::max<uint32_t>(1, uint32_t(src.size()));
    textures_ = vk::Image(cmd.allocator(), {VK_FORMAT_R8G8B8A8_SRGB, size, size, layers,
                                            VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                            "material-textures", levels, true});
    std::vector<uint8_t> data;
    std::vector<VkBufferImageCopy> regions;
    for (uint32_t layer = 0; layer < layers; ++layer) {
        for (uint32_t level = 0, s = size; level < levels; ++level, s = std::max(1u, s / 2)) {
            const size_t offset = data.size();
            data.resize(offset + size_t(s) * s * 4, 0xFF);  // no texture: white
            if (layer < src.size()) {
                const Texture& t = src[layer];
                if (t.width == 0 || t.rgba8.size() != size_t(t.width) * t.height * 4)
                    throw vk::VulkanError("texture " + std::to_string(layer) + " has no or inconsistent texels");
                if (!stbir_resize_uint8_srgb(t.rgba8.data(), int(t.width), int(t.height), 0, data.data() + offset,
                                             int(s), int(s), 0, 4, 3, 0))
                    throw vk::VulkanError("cannot resample texture " + std::to_string(layer));
            }
            VkBufferImageCopy r{};
            r.bufferOffset = offset;
            r.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, layer, 1};
            r.imageExtent = {s, s, 1};
            regions.push_back(r);
        }
    }
    cmd.uploadImage(textures_, data.data(), data.size(), regions);
    sampler_ = vk::Sampler(ctx_, {VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_REPEAT, false, true});
}

}  // namespace penumbra
