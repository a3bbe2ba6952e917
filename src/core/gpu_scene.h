// The long-lived GPU copy of a scene: geometry, materials, textures and samplers, uploaded once and
// shared by every Renderer (and every settings change) that draws the scene, plus per-scene data a
// module owns (hair strands: src/dsm), made on first use and kept as long as the scene.
// Frame pipelines (src/renderer/renderer.h) are built per settings on top of it.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <typeindex>

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
    vk::Context& context() { return ctx_; }
    // How many times geometry (vertices, indices, strands) was uploaded: 1 for the scene's lifetime.
    uint32_t geometryUploads() const { return geometryUploads_; }
    // Device memory the scene holds.
    VkDeviceSize bytes() const { return alloc_.bytesInUse(); }

    // The module's data of type T for this scene: made by `make` (with the scene's upload context)
    // the first time any renderer asks, the same object after. `make` may return null (nothing to
    // upload), which is kept too.
    template <class T>
    T* attachment(const std::function<std::unique_ptr<T>(vk::CommandContext&, const Scene&)>& make) {
        const std::type_index key(typeid(T));
        auto it = attachments_.find(key);
        if (it == attachments_.end())
            it = attachments_.emplace(key, std::shared_ptr<T>(make(cmd_, scene_))).first;
        return static_cast<T*>(it->second.get());
    }

private:
    vk::Context& ctx_;
    Scene scene_;
    vk::Allocator alloc_;
    vk::CommandContext cmd_;
    std::unique_ptr<SceneGpu> meshes_;
    std::map<std::type_index, std::shared_ptr<void>> attachments_;
    uint32_t geometryUploads_ = 0;
};

}  // namespace penumbra
