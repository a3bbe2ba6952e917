// Folds the indirect-irradiance contributions of a frame (names::kIrradianceContribution, any number
// of techniques) into the one image the lighting pass reads: none gives nothing, one is used as it
// is, more are added pairwise into images of the camera's size ("gi.sum" passes).
#pragma once
#include <memory>
#include <vector>

#include "core/frame_graph.h"
#include "vk/pipeline.h"

namespace penumbra {

class IrradianceSum {
public:
    IrradianceSum(vk::Allocator& alloc, uint32_t width, uint32_t height);
    // The sum of the frame's contributions (an invalid handle when there are none); afterwards the
    // contribution list holds only the sum.
    ImageHandle addTo(FrameGraph& graph);

private:
    vk::Allocator& alloc_;
    uint32_t width_, height_;
    vk::ComputeKernel kernel_;
    vk::Sampler linear_;
    std::vector<std::unique_ptr<vk::Image>> sums_;  // one per pairwise step, made when first needed
};

}  // namespace penumbra
