// Camera translucency: hair strands and alphaMode BLEND surfaces composited over the lit opaque
// image in depth order, with the deep shadow map's machinery (per-pixel runs of fragments, sorted in
// compute; the build's depth buckets leave out what lies behind the cap's bucket). Techniques compose by name only: the build reads the opaque depth
// ("gbuffer.depth") and "views"; the composite reads and rewrites the lit image ("hdr") after the
// lighting pass, with the lights' shadow maps ("shadow.*"), deep shadow maps ("dsm.*") and the
// indirect irradiance ("gi.irradiance"), so it works behind any camera path that publishes them.
//
// Frame: oit.clear (the counts only in the first frame: oit.sort zeroes what it read) -> oit.count (raster; hair in compute, oit.count.hair, with `computeHair`: see
// dsm/ribbon_raster.glsl; each fragment counted in its pixel's depth bucket) -> oit.offsets (per
// pixel: a run for the buckets up to the cap's) -> oit.build (.hair; the same passes again, the kept
// buckets' fragments stored in the runs) -> ... lighting ... -> oit.hair-shadow (per hair point: the
// shadow of each light with a DSM) -> oit.sort (per pixel: its nearest layers) -> oit.shade (per kept
// layer: its light) -> oit.blend (per pixel: front to back over "hdr").
#pragma once
#include <array>
#include <string>
#include <vector>

#include "dsm/hair_gpu.h"
#include "core/frame_graph.h"

namespace penumbra {

struct OitFrameStats {
    uint64_t fragments = 0;      // translucent camera fragments in front of the opaque surface
    uint64_t capacity = 0;       // nodes in the pool
    uint64_t overflow = 0;       // dropped because the pool was full
    uint64_t kept = 0;           // composited
    uint64_t beyondMaxList = 0;  // dropped beyond OIT_MAX_LIST per pixel (the farthest)
    uint64_t leftOut = 0;        // of those, in depth buckets the build never stored
    uint32_t longest = 0;
    uint64_t poolBytes = 0;
};

class CameraTranslucency {
public:
    // `hair` may be null. Nothing is allocated when the scene has neither hair nor BLEND materials.
    CameraTranslucency(vk::Allocator& alloc, SceneGpu& scene, const HairGpu* hair, uint32_t width, uint32_t height,
                       bool computeHair = false);
    bool active() const { return hair_ || hasBlended_; }
    // oit.clear, oit.count, oit.offsets and oit.build (after the G-buffer); `viewProj` the camera's.
    void addBuildTo(FrameGraph& graph, const RibbonView& camera, const glm::mat4& viewProj);
    // oit.sort, oit.shade and oit.blend (after lighting, before the tone mapper).
    void addCompositeTo(FrameGraph& graph);
    OitFrameStats readStats(vk::CommandContext& cmd) const;
    // Per scene light and hair point (HairGpu::points): the shadow of each light with a DSM there.
    const vk::Buffer& hairShadow() const { return hairShadow_; }

    // 100k strands of the hair scene make 29.5M camera fragments at 1080p (14 per pixel); 8 per pixel
    // would drop 44% of them. Capped by what one storage buffer addresses (lavapipe: 8.4M).
    static constexpr uint32_t kNodesPerPixel = 16;
    static constexpr VkDeviceSize kNodeBytes = 16 + 4;  // node + normal
    static constexpr uint32_t kBuckets = OIT_BUCKETS;  // depth buckets per pixel

private:
    void createBuildPipelines(vk::Context& ctx, bool computeHair);
    void createKernels(vk::Context& ctx);
    void addBuildPasses(FrameGraph& graph, const gpu::OitBuildPush& push, const std::string& name);
    void addHairShadowTo(FrameGraph& graph);
    PassBuilder& declareShadows(PassBuilder& pass) const;
    void recordBuild(VkCommandBuffer cmd, const gpu::OitBuildPush& cameraPush) const;
    gpu::OitBuildPush cameraPush(const RibbonView& camera, const glm::mat4& viewProj, BuildStep step) const;
    PassBuilder& declareLists(PassBuilder& pass) const;
    vk::Allocator& alloc_;
    SceneGpu& scene_;
    const HairGpu* hair_;
    bool hasBlended_;
    Bounds casters_;  // Scene::translucentCasterBounds: the depth buckets' range
    uint32_t bucketCount_ = 1;
    uint32_t width_, height_;
    uint64_t capacity_ = 0;
    vk::Buffer heads_, nodes_, normals_, stats_;
    vk::Buffer buckets_, tails_;  // per pixel: fragments per depth bucket, and the sum of -log(1 - alpha)
    bool countsZeroed_ = false;   // buckets_ and tails_ filled with 0 once (then oit.sort keeps them so)
    vk::Buffer layers_, shadeArgs_;  // the kept layers (node, pixel) in pixel order, and their dispatch
    vk::Buffer hairShadow_;          // hairShadow() (4 bytes without hair)
    std::array<BufferHandle, 5> lists_;  // this frame's nodes, normals, stats, buckets, tails (addBuildTo)
    vk::DescriptorLayout buildLayout_;
    vk::Pipeline hairPipeline_, meshPipeline_;  // the raster's (hairPipeline_ without computeHair)
    vk::ComputeKernel hairKernel_, offsets_, sort_, args_, shade_, blend_, hairShadowKernel_;
    vk::Sampler nearest_, border_, moments_;
};

std::string describeTranslucency(const OitFrameStats& s);
std::vector<std::string> translucencyWarnings(const OitFrameStats& s);

}  // namespace penumbra
