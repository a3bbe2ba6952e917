// The temporal-GI module: accumulates the frame's indirect irradiance (the sum of its contributions)
// over frames, reprojected (temporal_gi/gi_history.h), and hands the lighting the accumulation as
// the one contribution. Off by default (`--gi-temporal`).
#pragma once
#include "core/irradiance_sum.h"
#include "core/technique.h"
#include "temporal_gi/gi_history.h"

namespace penumbra {

struct TemporalGiSettings {
    float alpha = 0.1f;  // the new frame's weight
};

class TemporalGiTechnique : public Technique {
public:
    TemporalGiTechnique(const TechniqueBuild& b, const TemporalGiSettings& s);
    const char* name() const override { return "temporal-gi"; }
    void addPasses(const FrameContext& f) override;
    void setSettings(const TemporalGiSettings& s) { settings_ = s; }

private:
    TemporalGiSettings settings_;
    IrradianceSum sum_;
    GiHistory history_;
};

}  // namespace penumbra
