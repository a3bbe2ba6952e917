#include "core/gpu_scene.h"

namespace penumbra {

GpuScene::GpuScene(vk::Context& ctx, Scene scene)
    : ctx_(ctx), scene_(std::move(scene)), alloc_(ctx), cmd_(alloc_) {
    ensureSceneGraph(scene_);
    meshes_ = std::make_unique<SceneGpu>(cmd_, scene_);
    ++geometryUploads_;
}

GpuScene::~GpuScene() {
    attachments_.clear();  // before the allocator they were made with
}

}  // namespace penumbra
