// Hair ribbons in the camera's G-buffer and in ordinary shadow maps (lights without a deep shadow
// map: there hair is an opaque caster, which gives the binary shadows DSM is compared against).
#pragma once
#include "dsm/hair_gpu.h"
#include "core/frame_graph.h"

namespace penumbra {

// After the G-buffer pass, into the same targets (loaded, depth-tested): albedo = strand colour,
// normal = tangent with SHADING_HAIR in w.
class HairGBufferPass {
public:
    HairGBufferPass(vk::Allocator& alloc, const HairGpu& hair);
    // Draws into the published G-buffer ("gbuffer.*"; its depth D32_SFLOAT), row 0 of "views".
    void addTo(FrameGraph& graph, const RibbonView& camera);

private:
    void makePipeline(const vk::Image& albedo, const vk::Image& normal, const vk::Image& depth);
    vk::Allocator& alloc_;
    const HairGpu& hair_;
    vk::DescriptorLayout layout_;
    vk::Pipeline pipeline_;
};

// One shadow-map layer hair is drawn into, with the views row of its matrix.
struct HairShadowLayer {
    uint32_t layer;
    uint32_t viewRow;
    RibbonView view;
};

// Depth-only ribbons into layers of a D32 array image already holding the opaque casters (loaded).
class HairShadowPass {
public:
    HairShadowPass(vk::Allocator& alloc, const HairGpu& hair, float depthBiasConstant, float depthBiasSlope);
    // Draws into layers of "shadow.map" with rows of "views".
    void addTo(FrameGraph& graph, std::vector<HairShadowLayer> layers);
    void setBias(float constant, float slope) { biasConstant_ = constant, biasSlope_ = slope; }

private:
    vk::Allocator& alloc_;
    const HairGpu& hair_;
    float biasConstant_, biasSlope_;
    vk::DescriptorLayout layout_;
    vk::Pipeline pipeline_;
};

}  // namespace penumbra
