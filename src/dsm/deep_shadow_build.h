// DSM build: clears the depth buckets' counts, then rasterizes every semi-transparent caster (hair
// ribbons, alphaMode BLEND meshes) in each DSM light's view twice: dsm.count counts every fragment in
// its texel's depth bucket, dsm.offsets gives each texel a run for the buckets up to the list cap's
// (dsm/offsets.comp), and dsm.build stores those buckets' fragments, (depth, alpha), in the runs
// (dsm/dsm_insert.glsl; shared/types.h has the layout). No attachments and no depth test among
// translucent casters: the resolve sorts each run; only fragments hidden behind the opaque casters'
// shadow map are skipped. With `computeHair` the hair ribbons are rasterized in compute instead
// (dsm/ribbon_raster.glsl), in passes of their own (dsm.count.hair, dsm.build.hair).
#pragma once
#include "dsm/dsm_resources.h"
#include "core/frame_graph.h"

namespace penumbra {

class DeepShadowBuildPass {
public:
    // `hair` may be null (a scene without strands).
    // `depthTest`: fragments hidden behind the light's opaque casters (its ordinary shadow map,
    // "shadow.map") everywhere a lit receiver could look them up take no node (dsm/dsm_insert.glsl).
    DeepShadowBuildPass(vk::Allocator& alloc, SceneGpu& scene, const HairGpu* hair, DsmResources& res,
                        bool depthTest, bool computeHair);
    void addTo(FrameGraph& graph);

private:
    void addRasterPasses(FrameGraph& graph, BuildStep step);
    void recordLayer(VkCommandBuffer cmd, uint32_t layer, BuildStep step) const;
    gpu::DsmBuildPush layerPush(uint32_t layer, BuildStep step) const;
    glm::vec2 casterDepthRange(const RibbonView& view) const;
    PassBuilder& declareLists(PassBuilder& pass) const;
    const vk::Pipeline& setLayoutPipeline() const { return hairPipeline_.handle() ? hairPipeline_ : meshPipeline_; }
    vk::Allocator& alloc_;
    SceneGpu& scene_;
    const HairGpu* hair_;
    DsmResources& res_;
    bool hasBlended_;
    Bounds casters_;  // Scene::translucentCasterBounds
    bool depthTest_;
    vk::Sampler nearest_;
    vk::DescriptorLayout layout_;
    vk::Pipeline hairPipeline_, meshPipeline_;  // the raster's (hairPipeline_ without computeHair)
    vk::ComputeKernel hairKernel_;               // with computeHair
    vk::ComputeKernel offsets_;
    BufferHandle buckets_, runs_, stats_;        // this frame's, set by addTo
};

}  // namespace penumbra
