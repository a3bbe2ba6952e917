// The scene's GPU copy: every mesh's vertices and indices (uploaded once), the material table and its
// textures (at their own sizes, in a texture table bound as set 1). Shared, read-only, by every pass
// that draws the scene (G-buffer, shadow maps, RSM, DSM).
// Meshes are drawn per instance (Scene::instances); the instances' transforms are per-frame data in
// the frame graph's "instances" buffer (GpuInstance, written by the Renderer).
#pragma once
#include <vector>

#include "core/frame_graph.h"
#include "core/scene_bindings.h"  // shaders/core: the sets' binding numbers
#include "core/texture_upload.h"
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
    // Every drawn triangle as (instance, triangle): what a compute pass walks to draw the scene.
    const vk::Buffer& drawnTriangles() const { return drawnTriangles_; }
    uint32_t drawnTriangleCount() const { return drawnTriangleCount_; }
    // Scene::instances' world transforms at rest (t = 0, no animation).
    const std::vector<glm::mat4>& restTransforms() const { return restTransforms_; }
    // The frame's instance transforms decide the cull mode of mirrored instances (set before recording).
    void setFrameInstances(const std::vector<glm::mat4>& transforms);
    // The base-colour textures at their own sizes with their full mip chains: one 2D array per size
    // (texturePlan() says which texture is in which slot and layer; a last 1x1 white array fills the
    // table's unused slots). Sampled through the texture table, set 1 of every pipeline that draws
    // the scene (core/material_textures.glsl).
    const std::vector<vk::Image>& textures() const { return textures_; }
    const TextureTablePlan& texturePlan() const { return texturePlan_; }
    // GPU memory of the textures' images (the scene's, without the white filler).
    VkDeviceSize textureBytes() const;
    // The table's MATERIAL_TEXTURE_SLOTS plus a pass's own sampled images against the device's per
    // stage; throws std::invalid_argument naming both.
    static void checkTextureTable(const vk::DeviceLimits& limits);
    // Set 0 of the pipelines that draw the scene: views and materials (SCENE_VIEWS, SCENE_MATERIALS)
    // and the frame's instance table (SCENE_INSTANCES_BINDING, the graph's "instances"); a pass may declare more
    // bindings of its own. Set 1: the texture table. Both are bound by declareDrawSet.
    void declareDrawSet(PassBuilder& pass, BufferHandle views);
    // The frame's instance table ("instances"), or the table at rest in graphs without one (tests).
    BufferHandle instanceTable(FrameGraph& graph) const;
    // The set layouts of such a pipeline: `set0` (made from drawSetBindings() and the pass's own),
    // then the texture table's.
    static std::vector<VkDescriptorSetLayout> drawLayouts(vk::Context& ctx, VkDescriptorSetLayout set0);
    static VkDescriptorSetLayout textureTableLayout(vk::Context& ctx);
    static std::vector<vk::Binding> drawSetBindings();
    // The triangles as compute resolves of visibility IDs fetch them (core/visibility.glsl):
    // vertices, indices, triangle materials and the drawn (instance, triangle) list (SCENE_VERTICES
    // and on, with the draw set).
    void declareTriangles(PassBuilder& pass);
    static std::vector<vk::Binding> resolveSetBindings();
    // The rows of the instance table for these transforms (Scene::instances' order): normal matrix,
    // mirror flag, the instance's first drawn triangle (visibility IDs) and the map to where it was
    // in the previous frame (`previous`: the previous frame's transforms; empty = they did not move).
    std::vector<gpu::GpuInstance> instanceRows(const std::vector<glm::mat4>& transforms,
                                               const std::vector<glm::mat4>& previous = {}) const;
    // Draw `d`'s first triangle within its mesh. A visibility ID is the drawn-triangle index + 1:
    // the instance's base (GpuInstance.info.y) + this + gl_PrimitiveID + 1 (core/visibility.glsl).
    uint32_t triangleBase(const Draw& d) const { return drawTriangleInMesh_[size_t(&d - scene_.draws.data())]; }

    // Vertex input of penumbra::Vertex for GraphicsDesc.
    static uint32_t vertexStride() { return sizeof(Vertex); }
    static std::vector<VkVertexInputAttributeDescription> vertexAttributes();
    static VkFrontFace sceneFrontFace(bool yFlippedProjection) {
        return yFlippedProjection ? VK_FRONT_FACE_COUNTER_CLOCKWISE : VK_FRONT_FACE_CLOCKWISE;
    }

    // Binds vertex/index buffers, then, for every run of instances of one mesh (consecutive in
    // Scene::instances, all mirrored or none) and every draw of that mesh, calls `perDraw` (to push
    // constants) and draws the run with one instanced draw (firstInstance = the run's first instance).
    // `filter` selects draws by material (e.g. only alpha-masked ones). Single-sided materials are
    // drawn with back faces culled, in the camera and in the lights' views alike (glTF: a one-sided
    // surface is invisible from behind, so it neither shows nor casts from there — a sky dome seen
    // from outside casts no shadow); pipelines must use GraphicsDesc::dynamicCullMode.
    // Winding: glTF fronts are counter-clockwise; views with a y-flipped projection (the camera)
    // keep that, views without (shadow maps) see them clockwise: see sceneFrontFace().
    // `layers` > 1: layered passes draw `layers` instances per scene instance, one per target layer
    // (shadow maps; core/instances.glsl).
    template <class PerDraw, class Filter>
    void draw(VkCommandBuffer cmd, PerDraw perDraw, Filter filter, uint32_t layers = 1) const;

private:
    void uploadTextures(vk::CommandContext& cmd);
    const Scene& scene_;
    vk::Context& ctx_;
    vk::Buffer vertices_, indices_, materials_, triangleMaterials_, drawnTriangles_;
    uint32_t drawnTriangleCount_ = 0;
    std::vector<uint32_t> instanceTriangleBase_;  // per instance: index of its first drawn triangle
    std::vector<uint32_t> drawTriangleInMesh_;    // per draw: triangles of its mesh's earlier draws
    struct Run {
        uint32_t mesh, first, count;
        bool mirrored;
    };
    std::vector<Run> runs_;  // this frame's
    std::vector<glm::mat4> restTransforms_;  // Scene::instances' transforms at rest (t = 0)
    vk::Buffer restInstances_;  // the instance table at rest, for graphs without a frame's "instances"
    TextureTablePlan texturePlan_;
    std::vector<vk::Image> textures_;
    vk::Sampler sampler_;
    vk::DescriptorSet textureTable_;
};

template <class PerDraw, class Filter>
void SceneGpu::draw(VkCommandBuffer cmd, PerDraw perDraw, Filter filter, uint32_t layers) const {
    VkDeviceSize offset = 0;
    VkBuffer vb = vertices_.handle();
    vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &offset);
    vkCmdBindIndexBuffer(cmd, indices_.handle(), 0, VK_INDEX_TYPE_UINT32);
    for (const Run& run : runs_) {
        const Mesh& mesh = scene_.meshes[run.mesh];
        // A mirroring transform turns counter-clockwise fronts clockwise: cull the other side.
        const VkCullModeFlags back = run.mirrored ? VK_CULL_MODE_FRONT_BIT : VK_CULL_MODE_BACK_BIT;
        for (uint32_t k = mesh.firstDraw; k < mesh.firstDraw + mesh.drawCount; ++k) {
            const Draw& d = scene_.draws[k];
            if (!filter(scene_.materials[d.material])) continue;
            vkCmdSetCullMode(cmd, scene_.materials[d.material].doubleSided ? VkCullModeFlags(VK_CULL_MODE_NONE) : back);
            perDraw(d);
            vkCmdDrawIndexed(cmd, d.indexCount, run.count * layers, d.firstIndex, 0, run.first);
        }
    }
}

}  // namespace penumbra
