#include "lpv/lpv_technique.h"

#include "core/gpu_scene.h"
#include "core/names.h"

namespace penumbra {

LpvTechnique::LpvTechnique(const TechniqueBuild& b, const LpvSettings& s)
    : volume_(b.alloc, b.core.width, b.core.height, s, b.scene.scene().bounds) {
    b.board.put(names::kLpvCascadeBoxes, &boxes_, this);
    b.board.put(names::kGiChange, &volume_.changeTexel(), this);
}

void LpvTechnique::addPasses(const FrameContext& f) {
    const OccupancyState* occupancy = f.board.get(names::kOccupancyState);
    volume_.update(f.camera.eye);
    const gpu::LpvPush& c = volume_.constants();
    boxes_.boxes.resize(volume_.cascadeCount());
    for (uint32_t k = 0; k < volume_.cascadeCount(); ++k)
        boxes_.boxes[k] = {glm::vec3(c.cascades[k].origin), c.cascades[k].cellSize * float(c.resolution)};
    volume_.addTo(f.graph, f.board.require(names::kRsmLayerCount), occupancy ? occupancy->generation : 0,
                  f.board.get(names::kGiAccumulation), f.slot);
    f.graph.contribute(names::kIrradianceContribution, f.graph.image(names::kIrradiance));
}

}  // namespace penumbra
