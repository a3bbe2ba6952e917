// DSM build: clears the head pointers and the node counter, then rasterizes every semi-transparent
// caster (hair ribbons, alphaMode BLEND meshes) in each DSM light's view; every fragment pushes a
// (depth, alpha) node onto its texel's list (dsm/dsm_insert.glsl). No attachments and no depth test
// among translucent casters: all layers are kept, in drawing order (the resolve sorts them); only
// fragments hidden behind the opaque casters' shadow map are skipped. With `computeHair` the hair
// ribbons are rasterized in compute instead (dsm/ribbon_raster.glsl), in a pass of their own.
#pragma once
#include "dsm/dsm_resources.h"
#include "render/frame_graph.h"

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
    void recordLayer(VkCommandBuffer cmd, uint32_t layer) const;
    gpu::HairDrawPush layerPush(uint32_t layer) const;
    PassBuilder& declareLists(PassBuilder& pass) const;
    const vk::Pipeline& setLayoutPipeline() const { return hairPipeline_.handle() ? hairPipeline_ : meshPipeline_; }
    vk::Allocator& alloc_;
    SceneGpu& scene_;
    const HairGpu* hair_;
    DsmResources& res_;
    bool hasBlended_ = false;
    Bounds casters_;  // of the translucent casters (hair; with BLEND meshes the whole scene): the depth buckets' range
    bool depthTest_;
    vk::Sampler nearest_;
    vk::DescriptorLayout layout_;
    vk::Pipeline hairPipeline_, meshPipeline_;  // the raster's (hairPipeline_ without computeHair)
    vk::ComputeKernel hairKernel_;               // with computeHair
    BufferHandle buckets_, nodes_, stats_;       // this frame's, set by addTo
};

}  // namespace penumbra
