// Deep opacity maps (Yuksel & Keyser 2008; `--shadow dom`), the volumetric technique DSM is compared
// against: per texel of each map the nearest strand's depth and DOM_LAYERS layers of accumulated
// optical depth behind it, built from the hair in two compute walks over the strands
// (dsm/opacity_build.comp) and read by the DSM lookup in place of the lists (dsm/dsm_lookup.glsl).
// It shares DsmResources: the heads hold the first depths, node t the layers of texel t. Hair only:
// blended meshes get a warning.
//
// Frame: dom.clear -> dom.depth -> dom.layers (then lighting reads "dsm.*" as for the lists).
#pragma once
#include "dsm/dsm_resources.h"
#include "core/frame_graph.h"

namespace penumbra {

class DeepOpacityBuildPass {
public:
    DeepOpacityBuildPass(vk::Allocator& alloc, const HairGpu& hair, DsmResources& res);
    void addTo(FrameGraph& graph);

    // The layer thickness for `hair`: DOM_LAYERS layers span half the diameter of the strands' bounds
    // (receivers deeper in the hair see the total; behind the head the opaque map shadows anyway).
    static float layerThickness(const Scene& scene);

private:
    const HairGpu& hair_;
    DsmResources& res_;
    vk::ComputeKernel kernel_;
};

}  // namespace penumbra
