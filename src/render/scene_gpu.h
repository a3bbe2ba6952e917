// The scene's GPU copy: world-space vertices and indices, the material table and its textures.
// Shared, read-only, by every pass that draws the scene (G-buffer, shadow maps, later RSM/DSM).
#pragma once
#include <vector>

#include "render/frame_graph.h"
#include "scene/scene.h"
#include "shared/types.h"
#include "vk/commands.h"
#include "vk/pipeline.h"

namespace penumbra {

class SceneGpu {
public:
    SceneGpu(vk::CommandContext& cmd, const Scene& scene);
    SceneGpu(const SceneGpu&) = delete;
    SceneGpu& operator=(const SceneGpu&) = delete;

    const Scene& scene() const { return scene_; }
    const vk::Buffer& vertices() const { return vertices_; }
    const vk::Buffer& indices() const { return indices_; }
    const vk::Buffer& materials() const { return materials_; }
    // The material of every triangle (index / 3), for passes that fetch triangles themselves.
    const vk::Buffer& triangleMaterials() const { return triangleMaterials_; }
    // All base-colour textures as layers of one mip-mapped sRGB 2D array (one descriptor, which
    // fits every device's per-stage sampler limit; lavapipe allows only 32 samplers per stage).
    vk::Image& textures() { return textures_; }
    VkSampler textureSampler() const { return sampler_.handle(); }
    // Set 0 of the pipelines that draw the scene: views, materials, textures (bindings 0-2); a pass
    // may declare more bindings of its own.
    void declareDrawSet(PassBuilder& pass, BufferHandle views);
    static std::vector<vk::Binding> drawSetBindings();
    // The triangles as compute resolves of visibility IDs fetch them (render/visibility.glsl):
    // vertices, indices, triangle materials at bindings 12-14 (with the draw set's 0-2).
    void declareTriangles(PassBuilder& pass);
    static std::vector<vk::Binding> resolveSetBindings();
    // The visibility ID base of draw `d` (its first triangle; IDs are base + gl_PrimitiveID + 1).
    static uint32_t triangleBase(const Draw& d) { return d.firstIndex / 3; }

    // Vertex input of penumbra::Vertex for GraphicsDesc.
    static uint32_t vertexStride() { return sizeof(Vertex); }
    static std::vector<VkVertexInputAttributeDescription> vertexAttributes();
    static VkFrontFace sceneFrontFace(bool yFlippedProjection) {
        return yFlippedProjection ? VK_FRONT_FACE_COUNTER_CLOCKWISE : VK_FRONT_FACE_CLOCKWISE;
    }

    // Binds vertex/index buffers, then calls `perDraw` for every draw (to push constants), then draws.
    // `filter` selects draws by material (e.g. only alpha-masked ones). Single-sided materials are
    // drawn with back faces culled, in the camera and in the lights' views alike (glTF: a one-sided
    // surface is invisible from behind, so it neither shows nor casts from there — a sky dome seen
    // from outside casts no shadow); pipelines must use GraphicsDesc::dynamicCullMode.
    // Winding: glTF fronts are counter-clockwise; views with a y-flipped projection (the camera)
    // keep that, views without (shadow maps) see them clockwise: see sceneFrontFace().
    // `instances` > 1: layered passes draw one instance per target layer (shadow maps).
    template <class PerDraw, class Filter>
    void draw(VkCommandBuffer cmd, PerDraw perDraw, Filter filter, uint32_t instances = 1) const;

private:
    void uploadTextures(vk::CommandContext& cmd);
    const Scene& scene_;
    vk::Context& ctx_;
    vk::Buffer vertices_, indices_, materials_, triangleMaterials_;
    vk::Image textures_;
    vk::Sampler sampler_;
};

template <class PerDraw, class Filter>
void SceneGpu::draw(VkCommandBuffer cmd, PerDraw perDraw, Filter filter, uint32_t instances) const {
    VkDeviceSize offset = 0;
    VkBuffer vb = vertices_.handle();
    vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &offset);
    vkCmdBindIndexBuffer(cmd, indices_.handle(), 0, VK_INDEX_TYPE_UINT32);
    for (const Draw& d : scene_.draws) {
        if (!filter(scene_.materials[d.material])) continue;
        vkCmdSetCullMode(cmd, scene_.materials[d.material].doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT);
        perDraw(d);
        vkCmdDrawIndexed(cmd, d.indexCount, instances, d.firstIndex, 0, 0);
    }
}

}  // namespace penumbra
