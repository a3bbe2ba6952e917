// The occupancy volume as a shared service module: voxelizes the scene when its instances move and
// publishes the bits ("occupancy", names::kOccupancy) and its build count (names::kOccupancyState)
// for whichever technique reads them (the RSM gather's visibility, LPV's blocking).
#pragma once
#include "core/names.h"
#include "core/technique.h"
#include "voxel/occupancy_volume.h"

namespace penumbra {

class OccupancyTechnique : public Technique {
public:
    OccupancyTechnique(const TechniqueBuild& b, uint32_t resolution);
    ~OccupancyTechnique() override;
    const char* name() const override { return "occupancy"; }
    void addPasses(const FrameContext& f) override;
    void invalidateCaches(CacheDrop) override { volume_.invalidate(); }
    OccupancyVolume& volume() { return volume_; }

private:
    Blackboard& board_;
    OccupancyVolume volume_;
    OccupancyState state_;
};

}  // namespace penumbra
