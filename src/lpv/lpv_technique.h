// Light propagation volumes as a technique: injects the RSM (names::kRsmLayerCount and the "rsm.*"
// images), blocked by the occupancy volume when one is published (names::kOccupancyState), and
// contributes the volume's irradiance under names::kIrradianceContribution; publishes its cascades'
// boxes (names::kLpvCascadeBoxes) and, while a GI history is kept (names::kGiAccumulation), its
// temporal gradients (names::kGiChange).
#pragma once
#include "core/technique.h"
#include "lpv/lpv.h"
#include "lpv/lpv_names.h"

namespace penumbra {

class LpvTechnique : public Technique {
public:
    LpvTechnique(const TechniqueBuild& b, const LpvSettings& s);
    const char* name() const override { return "lpv"; }
    void addPasses(const FrameContext& f) override;
    bool contributesIrradiance() const override { return true; }
    void setSettings(const LpvSettings& s) { volume_.setSettings(s); }
    LightPropagationVolume& volume() { return volume_; }

private:
    LightPropagationVolume volume_;
    LpvCascadeBoxes boxes_;
};

}  // namespace penumbra
