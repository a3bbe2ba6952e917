#include "render/scene_gpu.h"

#include <algorithm>

#include "render/texture_upload.h"

namespace penumbra {

SceneGpu::SceneGpu(vk::CommandContext& cmd, const Scene& scene)
    : scene_(scene), ctx_(cmd.allocator().context()) {
    if (scene.indices.empty() && scene.strands.empty()) throw vk::VulkanError("scene has no triangles");
    // Visibility IDs are 32-bit: triangle + 1, 0 meaning nothing drawn (render/visibility.glsl).
    if (scene.indices.size() / 3 >= 0xFFFFFFFFull)
        throw vk::VulkanError("scene has more triangles than 32-bit visibility IDs can name");
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

std::vector<vk::Binding> SceneGpu::resolveSetBindings() {
    std::vector<vk::Binding> b = drawSetBindings();
    for (uint32_t k : {12u, 13u, 14u}) b.push_back({k, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
    return b;
}

void SceneGpu::declareTriangles(PassBuilder& pass) {
    FrameGraph& g = pass.graph();
    pass.storageBuffer(12, g.import(vertices_)).storageBuffer(13, g.import(indices_)).storageBuffer(
        14, g.import(triangleMaterials_));
}

void SceneGpu::uploadTextures(vk::CommandContext& cmd) {
    // Each texture at its own size is blitted into its square layer and the mips are blitted on the GPU
    // (render/texture_upload.h); the layer size is the largest texture's side (textureLayerSize).
    const std::vector<Texture>& src = scene_.textures;
    textures_ = uploadTextureArray(cmd, src, src.empty() ? 1 : textureLayerSize(src));
    sampler_ = vk::Sampler(ctx_, {VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_REPEAT, false, true});
}

}  // namespace penumbra
