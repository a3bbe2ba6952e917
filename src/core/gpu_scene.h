// The long-lived GPU copy of a scene: geometry, materials, textures, samplers and hair strands,
// uploaded once and shared by every Renderer (and every settings change) that draws the scene.
// Frame pipelines (src/renderer/renderer.h) are built per settings on top of it.
#pragma once
#include <memory>

#include "dsm/hair_gpu.h"
#include "core/scene_gpu.h"
#include "scene/scene.h"
#include "vk/commands.h"

namespace penumbra {

class GpuScene {
public:
    GpuScene(vk::Context& ctx, Scene scene);
    ~GpuScene();
    GpuScene(const GpuScene&) = delete;
    GpuScene& operator=(const GpuScene&) = delete;

    const Scene& scene() const { return scene_; }
    SceneGpu& meshes() { return *meshes_; }
    const HairGpu* hair() const { return hair_.get(); }
    vk::Context& context() { return ctx_; }
    // How many times geometry (vertices, indices, strands) was uploaded: 1 for the scene's lifetime.
    uint32_t geometryUploads() const { return geometryUploads_; }
    // Device memory the scene holds.
    VkDeviceSize bytes() const { return alloc_.bytesInUse(); }

private:
    vk::Context& ctx_;
    Scene scene_;
    vk::Allocator alloc_;
    vk::CommandContext cmd_;
    std::unique_ptr<SceneGpu> meshes_;
    std::unique_ptr<HairGpu> hair_;
    uint32_t geometryUploads_ = 0;
};

}  // namespace penumbra
