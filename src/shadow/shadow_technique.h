// The shadow-map family as a technique: the maps of every shadowed light (with other modules'
// casters drawn into them, names::kShadowCasters), their filtering into "shadow.mask", and the
// layers' host side published as names::kShadowLayers for the frame data and GI.
#pragma once
#include "core/names.h"
#include "core/technique.h"
#include "shadow/shadow_map_pass.h"

namespace penumbra {

class ShadowTechnique : public Technique {
public:
    // Reads names::kDeepShadowLights and names::kShadowCasters from the blackboard (built before).
    ShadowTechnique(const TechniqueBuild& b, const ShadowSettings& s);
    ~ShadowTechnique() override;
    const char* name() const override { return "shadow"; }
    void update(const FrameContext& f) override;
    void addPasses(const FrameContext& f) override;
    void invalidateCaches(CacheDrop) override { pass_.invalidate(); }
    void setSettings(const ShadowSettings& s) { pass_.setSettings(s); }
    // The sun's cascades move in whole blocks of this many texels (GI reads such a block as one
    // texel; the assembly knows which GI runs).
    void setCascadeSnap(uint32_t texels) { snapTexels_ = texels; }
    void setFilters(const ShadowSettings& s, const std::vector<Light>& lights);
    ShadowMapPass& pass() { return pass_; }

private:
    void publishLayers();
    Blackboard& board_;
    ShadowMapPass pass_;
    ShadowLayers layers_;
    uint32_t snapTexels_ = 1;
};

}  // namespace penumbra
