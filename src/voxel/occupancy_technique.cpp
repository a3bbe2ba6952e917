#include "voxel/occupancy_technique.h"

#include "core/gpu_scene.h"

namespace penumbra {

OccupancyTechnique::OccupancyTechnique(const TechniqueBuild& b, uint32_t resolution)
    : board_(b.board), volume_(b.alloc, b.scene.meshes(), resolution) {
    b.board.put(names::kOccupancyState, &state_, this);
}

OccupancyTechnique::~OccupancyTechnique() { board_.dropOwner(this); }

void OccupancyTechnique::addPasses(const FrameContext& f) {
    volume_.addTo(f.graph);
    state_.generation = volume_.generation();
}

}  // namespace penumbra
