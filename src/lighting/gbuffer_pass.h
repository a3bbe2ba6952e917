// The camera's G-buffer: albedo, world normal and depth per pixel, by one of two paths.
//   gbuffer:    one raster pass writes all three (scene.vert / gbuffer.frag; albedo sRGB 8-bit).
//   visibility: the raster writes depth and a 32-bit visibility ID only (core/visibility.frag;
//               alpha-masked materials still test alpha there), then a compute pass resolves albedo
//               (RGBA16F) and normal from the ID (lighting/visibility_resolve.comp; texture level of
//               detail from the neighbouring pixels' rays, as the raster's 2x2 quads take it).
// Each colour target a raster pass writes costs fill rate on GPUs whose raster path is narrow; the
// visibility path writes one 32-bit target, or none: with `computeRaster` the compute rasterizer
// (core/depth_raster.h) writes depth and ID with 64-bit atomics instead of the hardware.
#pragma once
#include <memory>

#include "core/core_settings.h"
#include "core/depth_raster.h"
#include "core/frame_graph.h"
#include "core/scene_gpu.h"

namespace penumbra {

class GBufferPass {
public:
    // `drawBlended`: alphaMode BLEND materials are drawn opaque (no camera translucency).
    // `rasterAfter`: raster passes test and write the depth afterwards (opaque hair ribbons), so it
    // stays D32_SFLOAT; else the compute rasterizer stores it as R32_SFLOAT (no copy).
    GBufferPass(vk::Allocator& alloc, SceneGpu& scene, uint32_t width, uint32_t height,
                VkDescriptorSetLayout drawLayout, CameraPath path, bool drawBlended = true, bool computeRaster = false,
                bool rasterAfter = false);
    // Reads "views" (and "frame"); publishes "gbuffer.albedo", "gbuffer.normal", "gbuffer.depth"
    // (and "gbuffer.ids" on the visibility path). `slot`: the frame in flight.
    void addTo(FrameGraph& graph, uint32_t slot = 0);
    CameraPath path() const { return path_; }

    vk::Image albedo, normal, depth, ids;

private:
    void addVisibility(FrameGraph& graph, ImageHandle a, ImageHandle n, ImageHandle d, uint32_t slot);
    void addVisibilityRaster(FrameGraph& graph, ImageHandle id, ImageHandle d);
    void addResolve(FrameGraph& graph, ImageHandle a, ImageHandle n, ImageHandle id);
    vk::Allocator& alloc_;
    SceneGpu& scene_;
    CameraPath path_;
    bool drawBlended_;
    vk::Pipeline pipeline_, masked_;  // gbuffer: pipeline_ only; visibility: opaque and masked ID pipelines
                                      // (none under the compute rasterizer)
    vk::DescriptorLayout resolveLayout_;
    vk::Pipeline resolve_;
    vk::Sampler nearest_;
    std::unique_ptr<DepthRaster> compute_;  // the visibility raster in compute (null: the hardware's)
};

}  // namespace penumbra
