// The temporal-GI module: accumulates the frame's indirect irradiance (the sum of its contributions)
// over frames, reprojected (temporal_gi/gi_history.h), filters it where its noise shows
// (temporal_gi/gi_filter.h), and hands the lighting the result as the one contribution. It tells
// the GI techniques whether this frame adds to a history (names::kGiAccumulation), so that they
// spread their samples over frames. The history restarts on the first frame, a camera cut and a light
// that changed by more than TemporalGiSettings::resetAngle; a smaller change raises the new frame's
// weight. On by default (`--gi-temporal off`: the single-frame estimate).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/irradiance_sum.h"
#include "core/names.h"
#include "core/technique.h"
#include "temporal_gi/gi_filter.h"
#include "temporal_gi/gi_history.h"
#include "temporal_gi/temporal_gi_settings.h"

namespace penumbra {

// How much the lights changed between two frames, as the least weight the new frame must get in the
// history (1: restart). `sceneSize`: the scene bounds' diagonal, the measure of a moving light.
float lightChangeWeight(const std::vector<Light>& before, const std::vector<Light>& now, float sceneSize,
                        float resetAngle);
// Whether the camera jumped (a cut): its history shows nothing of the new view worth keeping.
bool cameraCut(const Camera& before, const Camera& now, float sceneSize);

class TemporalGiTechnique : public Technique {
public:
    TemporalGiTechnique(const TechniqueBuild& b, const TemporalGiSettings& s);
    ~TemporalGiTechnique() override;
    const char* name() const override { return "temporal-gi"; }
    void update(const FrameContext& f) override;
    void addPasses(const FrameContext& f) override;
    // `estimator`: the GI techniques' settings in one string; when it changes, what the history holds
    // is another estimator's, and the history restarts.
    void setSettings(const TemporalGiSettings& s, const std::string& estimator);
    static uint64_t bytes(uint64_t width, uint64_t height);

private:
    Blackboard& board_;
    TemporalGiSettings settings_;
    float sceneSize_;
    IrradianceSum sum_;
    GiHistory history_;
    GiFilter filter_;
    GiAccumulation accumulation_;
    std::string estimator_;
    bool restart_ = true;  // the next frame starts a new history
    float changeWeight_ = 0.0f;
    uint32_t frames_ = 0;
    std::optional<Camera> lastCamera_;
    std::vector<Light> lastLights_;
};

}  // namespace penumbra
