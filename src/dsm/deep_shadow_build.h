// DSM build: clears the head pointers and the node counter, then rasterizes every semi-transparent
// caster (hair ribbons, alphaMode BLEND meshes) in each DSM light's view; every fragment pushes a
// (depth, alpha) node onto its texel's list (dsm/dsm_insert.glsl). No depth test and no attachments:
// all layers of translucency are kept, in drawing order (the resolve sorts them).
#pragma once
#include "dsm/dsm_resources.h"
#include "render/frame_graph.h"

namespace penumbra {

class DeepShadowBuildPass {
public:
    // `hair` may be null (a scene without strands).
    DeepShadowBuildPass(vk::Allocator& alloc, SceneGpu& scene, const HairGpu* hair, DsmResources& res);
    void addTo(FrameGraph& graph);

private:
    void recordLayer(VkCommandBuffer cmd, uint32_t layer) const;
    const vk::Pipeline& setLayoutPipeline() const { return hair_ ? hairPipeline_ : meshPipeline_; }
    vk::Allocator& alloc_;
    SceneGpu& scene_;
    const HairGpu* hair_;
    DsmResources& res_;
    bool hasBlended_ = false;
    vk::DescriptorLayout layout_;
    vk::Pipeline hairPipeline_, meshPipeline_;
};

}  // namespace penumbra
