#include "lpv/lpv_technique.h"

#include "core/gpu_scene.h"
#include "core/names.h"

namespace penumbra {

LpvTechnique::LpvTechnique(const TechniqueBuild& b, const LpvSettings& s)
    : volume_(b.alloc, b.core.width, b.core.height, s, b.scene.scene().bounds) {}

void LpvTechnique::addPasses(const FrameContext& f) {
    const OccupancyState* occupancy = f.board.get(names::kOccupancyState);
    volume_.update(f.camera.eye);
    volume_.addTo(f.graph, f.board.require(names::kRsmLayerCount), occupancy ? occupancy->generation : 0);
    f.graph.contribute(names::kIrradianceContribution, f.graph.image(names::kIrradiance));
}

}  // namespace penumbra
