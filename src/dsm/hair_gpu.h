// The scene's hair strands on the GPU, drawn as viewer-facing ribbons (dsm/hair.vert) by every pass
// that draws hair: the camera G-buffer, the ordinary shadow map and the deep-shadow-map build.
//
// Ribbons are expanded in the vertex shader from the strand points rather than built once on the
// CPU: a ribbon must face each view (camera and every light) and be at least one pixel or texel wide
// in it, so one static mesh cannot serve all views; pulling points costs 32 bytes per point and no
// index buffer (the strip's strand joins are degenerate, see hair.vert).
#pragma once
#include "core/scene_gpu.h"
#include "core/light_space.h"

namespace penumbra {

// Who a ribbon faces and how large a pixel/texel is there (every hair push's `view`).
using RibbonView = gpu::GpuRibbonView;

// `pixelPerDistance`: world size of a pixel at unit distance (FrameUniforms.pixelSpread).
RibbonView cameraRibbonView(const glm::vec3& eye, float pixelPerDistance);
// A shadow-map or DSM view of a directional or spot light.
RibbonView lightRibbonView(const Light& light, const LightProjection& projection);

// The translucent casters' builds (the DSM's and the camera's) make the same fragments twice: first
// they count them per depth bucket, then they store the kept buckets' (dsm/depth_buckets.glsl).
enum class BuildStep { Count, Store };
// `count` depth buckets over the casters' depths [range.x, range.y], for `step`.
gpu::GpuDepthBuckets depthBuckets(glm::vec2 range, uint32_t count, BuildStep step);
// How many depth buckets (`wanted`, or fewer where those would not fit one storage buffer) `cells`
// texels or pixels get.
uint32_t depthBucketCount(vk::Context& ctx, uint64_t cells, uint32_t wanted);

class HairGpu {
public:
    HairGpu(vk::CommandContext& cmd, const Scene& scene);

    // The points and the strands' colour and opacity (HAIR_POINTS, HAIR_STRANDS) of the hair pipelines' set 0.
    static std::vector<vk::Binding> bindings();
    void declare(PassBuilder& pass) const;
    // A ribbon pipeline: dsm/hair.vert, no vertex input, triangle strip, no culling.
    static vk::GraphicsDesc pipelineDesc(const std::string& fragmentShader);
    // Every ribbon of the scene in one draw; `push` (a hair push of dsm/types.h) says which view.
    template <class Push> void draw(VkCommandBuffer cmd, const vk::Pipeline& pipeline, const Push& push) const {
        pipeline.push(cmd, push);
        drawRibbons(cmd);
    }
    // A compute raster of the ribbons (dsm/ribbon_raster.glsl): set 0 holds the views and the hair
    // buffers (HAIR_*) that every such kernel reads, then the kernel's own `outputs`; `pushBytes`: its push's.
    static vk::ComputeKernel segmentKernel(vk::Context& ctx, const std::string& shader,
                                           const std::vector<vk::Binding>& outputs, uint32_t pushBytes);
    // Every ribbon segment in one dispatch of a compute raster (dsm/ribbon_raster.glsl: 64 segments
    // per group, groups in 2D); `push` says which view.
    template <class Push>
    void dispatchSegments(VkCommandBuffer cmd, const vk::Pipeline& pipeline, const Push& push) const {
        pipeline.push(cmd, push);
        dispatch64(cmd, pointCount() - 1);
    }
    // One invocation per drawn point (spatialPoints()), 64 per group, groups in 2D.
    void dispatchDrawnPoints(VkCommandBuffer cmd) const { dispatch64(cmd, drawnPointCount_); }

    const vk::Buffer& points() const { return points_; }
    const vk::Buffer& strands() const { return strands_; }
    // The drawn points' indices (not the zero-width copies') in the order of a Morton curve over their
    // positions: a pass that reads a map at every point takes them in this order, so that a warp's
    // reads are neighbours (hair is static: the order is made once).
    const vk::Buffer& spatialPoints() const { return spatialPoints_; }
    uint32_t strandCount() const { return strandCount_; }
    uint32_t pointCount() const { return vertexCount_ / 2; }  // with the zero-width copies bracketing strands
    VkDeviceSize bytes() const { return points_.size() + strands_.size(); }

private:
    static void dispatch64(VkCommandBuffer cmd, uint32_t invocations);
    void drawRibbons(VkCommandBuffer cmd) const;
    vk::Buffer points_, strands_, spatialPoints_;
    uint32_t vertexCount_ = 0, strandCount_ = 0, drawnPointCount_ = 0;
};

}  // namespace penumbra
