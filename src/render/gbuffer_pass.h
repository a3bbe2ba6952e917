// G-buffer: a thin raster pass writing albedo (sRGB), world normal and depth from the camera.
#pragma once
#include "render/frame_graph.h"
#include "render/scene_gpu.h"

namespace penumbra {

class GBufferPass {
public:
    GBufferPass(vk::Allocator& alloc, SceneGpu& scene, uint32_t width, uint32_t height,
                VkDescriptorSetLayout drawLayout);
    // Reads "views"; publishes "gbuffer.albedo", "gbuffer.normal", "gbuffer.depth".
    void addTo(FrameGraph& graph);

    vk::Image albedo, normal, depth;

private:
    vk::Allocator& alloc_;
    SceneGpu& scene_;
    vk::Pipeline pipeline_;
};

}  // namespace penumbra
