// Reflective shadow maps as a technique: the RSM of every shadowed light, rendered with the shadow
// layers' projections (names::kShadowLayers, whose visibility IDs it asks for); with `gather` (GI
// rsm) also the indirect light from it, contributed under names::kIrradianceContribution; without
// (GI lpv) only the RSM, for injection (names::kRsmLayerCount and the "rsm.*" images).
#pragma once
#include <memory>

#include "core/names.h"
#include "core/technique.h"
#include "rsm/rsm_flux.h"
#include "rsm/rsm_gather.h"
#include "rsm/rsm_pass.h"

namespace penumbra {

class RsmTechnique : public Technique {
public:
    // `shadowResolution`: the shadow maps', whose ID layers the RSM is resolved from.
    RsmTechnique(const TechniqueBuild& b, const RsmSettings& s, bool gather, uint32_t shadowResolution);
    ~RsmTechnique() override;
    const char* name() const override { return "rsm"; }
    void update(const FrameContext& f) override;
    void addPasses(const FrameContext& f) override;
    bool contributesIrradiance() const override { return gather_ != nullptr; }
    void setSettings(const RsmSettings& s);
    RsmPass& pass() { return pass_; }
    RsmGather* gather() { return gather_.get(); }
    RsmFluxSampler* flux() { return flux_.get(); }

private:
    Blackboard& board_;
    bool widestCascadeOnly_;
    RsmPass pass_;
    std::unique_ptr<RsmFluxSampler> flux_;  // --rsm-far flux
    std::unique_ptr<RsmGather> gather_;
    uint32_t layerCount_ = 0;  // names::kRsmLayerCount
};

}  // namespace penumbra
