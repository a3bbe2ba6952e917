#include "core/scene_gpu.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "core/texture_upload.h"
#include "scene/animation.h"

namespace penumbra {

SceneGpu::SceneGpu(vk::CommandContext& cmd, const Scene& scene)
    : scene_(scene), ctx_(cmd.allocator().context()) {
    if (scene.indices.empty() && scene.strands.empty()) throw vk::VulkanError("scene has no triangles");
    checkTextureTable(ctx_.limits());
    texturePlan_ = planTextureTable(scene.textures);
    // Visibility IDs are 32-bit: triangle + 1, 0 meaning nothing drawn (core/visibility.glsl).
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
        g.texture = hasTexture ? texturePlan_.handles[m.baseColorTexture] : NO_TEXTURE;
        g.alphaMode = uint32_t(m.alphaMode);
        g.doubleSided = m.doubleSided ? 1u : 0u;
        g.alphaCutoff = m.alphaCutoff;
        mats.push_back(g);
    }
    materials_ = cmd.createDeviceBuffer(mats.data(), mats.size() * sizeof(gpu::GpuMaterial),
                                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "materials");
    std::vector<uint32_t> triangleMaterials(std::max<size_t>(scene.indices.size() / 3, 1), 0u);
    for (const Draw& d : scene.draws)
        std::fill_n(triangleMaterials.begin() + d.firstIndex / 3, d.indexCount / 3, d.material);
    triangleMaterials_ = cmd.createDeviceBuffer(triangleMaterials.data(), triangleMaterials.size() * sizeof(uint32_t),
                                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "triangle-materials");
    // Every instance's triangles in its mesh's draw order: (instance, triangle) per visibility ID.
    drawTriangleInMesh_.assign(scene.draws.size(), 0u);
    for (const Mesh& mesh : scene.meshes)
        for (uint32_t k = mesh.firstDraw + 1; k < mesh.firstDraw + mesh.drawCount; ++k)
            drawTriangleInMesh_[k] = drawTriangleInMesh_[k - 1] + scene.draws[k - 1].indexCount / 3;
    std::vector<glm::uvec2> drawn;
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const Mesh& mesh = scene.meshes[scene.instances[i].mesh];
        instanceTriangleBase_.push_back(uint32_t(drawn.size()));
        for (uint32_t k = mesh.firstDraw; k < mesh.firstDraw + mesh.drawCount; ++k)
            for (uint32_t t = 0; t < scene.draws[k].indexCount / 3; ++t)
                drawn.push_back({i, scene.draws[k].firstIndex / 3 + t});
    }
    if (drawn.size() >= size_t(UINT32_MAX))
        throw std::runtime_error(fmt::format("the scene draws {} triangles: visibility IDs hold 2^32 - 1", drawn.size()));
    drawnTriangleCount_ = uint32_t(drawn.size());
    restTransforms_ = instanceTransforms(scene, nodeWorldTransforms(scene, 0.0, {}));
    std::vector<gpu::GpuInstance> rows = instanceRows(restTransforms_);
    restInstances_ = cmd.createDeviceBuffer(rows.data(), rows.size() * sizeof(rows[0]), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                            "rest-instances");
    setFrameInstances(restTransforms_);
    if (drawn.empty()) drawn.push_back({0u, 0u});
    drawnTriangles_ = cmd.createDeviceBuffer(drawn.data(), drawn.size() * sizeof(glm::uvec2),
                                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "drawn-triangles");
    uploadTextures(cmd);
}

std::vector<VkVertexInputAttributeDescription> SceneGpu::vertexAttributes() {
    return {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
            {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, normal)},
            {2, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(Vertex, uv)}};
}

std::vector<vk::Binding> SceneGpu::drawSetBindings() {
    return {{SCENE_VIEWS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
            {SCENE_MATERIALS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
            {SCENE_INSTANCES_BINDING, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
}

namespace {

// Set 1 (core/material_textures.glsl): the texture slots and their sampler.
std::vector<vk::Binding> textureTableBindings() {
    return {{SCENE_TEXTURES, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, MATERIAL_TEXTURE_SLOTS},
            {SCENE_TEXTURE_SAMPLER, VK_DESCRIPTOR_TYPE_SAMPLER}};
}

// Sampled images a pass that draws the scene may declare besides the table.
constexpr uint32_t kPassSampledImages = 4;

}  // namespace

VkDescriptorSetLayout SceneGpu::textureTableLayout(vk::Context& ctx) {
    return vk::DescriptorLayout(ctx, textureTableBindings(), false).handle();  // the device's cache owns it
}

std::vector<VkDescriptorSetLayout> SceneGpu::drawLayouts(vk::Context& ctx, VkDescriptorSetLayout set0) {
    return {set0, textureTableLayout(ctx)};
}

void SceneGpu::checkTextureTable(const vk::DeviceLimits& limits) {
    if (limits.sampledImagesPerStage < MATERIAL_TEXTURE_SLOTS + kPassSampledImages)
        throw std::invalid_argument(fmt::format("the device allows {} sampled images per shader stage; the material "
                                                "texture table needs {} plus {} for a pass's own",
                                                limits.sampledImagesPerStage, MATERIAL_TEXTURE_SLOTS,
                                                kPassSampledImages));
}

VkDeviceSize SceneGpu::textureBytes() const {
    VkDeviceSize bytes = 0;
    for (size_t i = 0; i < texturePlan_.slots.size(); ++i) bytes += textures_[i].bytes();
    return bytes;
}

void SceneGpu::declareDrawSet(PassBuilder& pass, BufferHandle views) {
    FrameGraph& g = pass.graph();
    pass.storageBuffer(SCENE_VIEWS, views).storageBuffer(SCENE_MATERIALS, g.import(materials_));
    std::vector<ImageHandle> textures;  // static after the upload: imported, only ever sampled
    for (vk::Image& t : textures_) textures.push_back(g.import(t));
    pass.descriptorSet(SCENE_TEXTURE_SET, textureTable_.handle(), textures);
    pass.storageBuffer(SCENE_INSTANCES_BINDING, instanceTable(g));
}

BufferHandle SceneGpu::instanceTable(FrameGraph& graph) const {
    return graph.hasBuffer("instances") ? graph.buffer("instances") : graph.import(restInstances_);
}

void SceneGpu::setFrameInstances(const std::vector<glm::mat4>& transforms) {
    runs_.clear();
    for (uint32_t i = 0; i < scene_.instances.size() && i < transforms.size(); ++i) {
        const uint32_t mesh = scene_.instances[i].mesh;
        const bool mirrored = glm::determinant(glm::mat3(transforms[i])) < 0.0f;
        if (!runs_.empty() && runs_.back().mesh == mesh && runs_.back().mirrored == mirrored &&
            runs_.back().first + runs_.back().count == i)
            ++runs_.back().count;
        else
            runs_.push_back({mesh, i, 1, mirrored});
    }
}

std::vector<gpu::GpuInstance> SceneGpu::instanceRows(const std::vector<glm::mat4>& transforms,
                                                     const std::vector<glm::mat4>& previous) const {
    std::vector<gpu::GpuInstance> rows;
    rows.reserve(transforms.size());
    for (size_t i = 0; i < transforms.size(); ++i) {
        const glm::mat4& m = transforms[i];
        const glm::mat3 linear(m);
        const float det = glm::determinant(linear);
        gpu::GpuInstance row{};
        row.model = m;
        row.normal = glm::mat4(std::abs(det) > 0.0f ? glm::transpose(glm::inverse(linear)) : linear);
        row.mirrored = det < 0.0f ? 1u : 0u;
        row.firstDrawnTriangle = i < instanceTriangleBase_.size() ? instanceTriangleBase_[i] : 0u;
        // A singular transform (scale 0) has no inverse: such an instance covers no pixel anyway.
        const bool moved = i < previous.size() && previous[i] != m && std::abs(det) > 0.0f;
        row.toPrevious = moved ? previous[i] * glm::inverse(m) : glm::mat4(1.0f);
        rows.push_back(row);
    }
    return rows;
}

std::vector<vk::Binding> SceneGpu::resolveSetBindings() {
    std::vector<vk::Binding> b = drawSetBindings();
    for (uint32_t k : {SCENE_VERTICES, SCENE_INDICES, SCENE_TRIANGLE_MATERIALS, SCENE_DRAWN_TRIANGLES})
        b.push_back({k, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
    return b;
}

void SceneGpu::declareTriangles(PassBuilder& pass) {
    FrameGraph& g = pass.graph();
    pass.storageBuffer(SCENE_VERTICES, g.import(vertices_))
        .storageBuffer(SCENE_INDICES, g.import(indices_))
        .storageBuffer(SCENE_TRIANGLE_MATERIALS, g.import(triangleMaterials_))
        .storageBuffer(SCENE_DRAWN_TRIANGLES, g.import(drawnTriangles_));
}

void SceneGpu::uploadTextures(vk::CommandContext& cmd) {
    // Each slot an array of one size, its mips blitted on the GPU (core/texture_upload.h).
    for (const TextureSlot& slot : texturePlan_.slots)
        textures_.push_back(uploadTextureSlot(cmd, scene_.textures, slot, "material-textures"));
    const std::vector<Texture> white{{1, 1, {255, 255, 255, 255}}};
    textures_.push_back(uploadTextureSlot(cmd, white, {1, 1, {0}}, "material-textures-unused"));
    sampler_ = vk::Sampler(ctx_, {VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_REPEAT, false, true});
    textureTable_ = vk::DescriptorSet(ctx_, textureTableBindings());
    vk::DescriptorWrites writes;
    for (uint32_t slot = 0; slot < MATERIAL_TEXTURE_SLOTS; ++slot)
        writes.sampledImage(0, slot, textures_[std::min<size_t>(slot, textures_.size() - 1)].view());
    writes.sampler(1, sampler_.handle());
    writes.update(ctx_.device(), textureTable_.handle());
}

}  // namespace penumbra
