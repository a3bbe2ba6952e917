// G-buffer: a thin raster pass writing albedo (sRGB), world normal and depth from the camera.
#pragma once
#include "render/frame_graph.h"
#include "render/scene_gpu.h"

namespace penumbra {

class GBufferPass {
public:
    // `drawBlended`: alphaMode BLEND materials are drawn opaque (no camera translucency).
    GBufferPass(vk::Allocator& alloc, SceneGpu& scene, uint32_t width, uint32_t height,
                VkDescriptorSetLayout drawLayout, bool drawBlended = true);
    // Reads "views"; publishes "gbuffer.albedo", "gbuffer.normal", "gbuffer.depth".
    void addTo(FrameGraph& graph);

    vk::Image albedo, normal, depth;

private:
    vk::Allocator& alloc_;
    SceneGpu& scene_;
    bool drawBlended_;
    vk::Pipeline pipeline_;
};

}  // namespace penumbra
