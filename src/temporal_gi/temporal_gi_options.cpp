#include "temporal_gi/temporal_gi_options.h"

namespace penumbra {
namespace {

using namespace change;

OptionTable makeTable() {
    using S = TemporalGiSettings;
    OptionTableBuilder<S> t("temporal_gi", "Temporal GI: accumulation over frames and the spatial filter");
    t.real("--gi-temporal-alpha", "min_weight", [](S& s) -> auto& { return s.minWeight; }, 1e-3, 1.0, kFrame,
           "The least weight of a new frame in the GI history (a still view averages up to 1/alpha frames)");
    t.real("--gi-reset-angle", "reset_angle", [](S& s) -> auto& { return s.resetAngle; }, 0.01, 180.0, kFrame,
           "Degrees a light turns in one frame that restart the GI history; a smaller turn raises the new "
           "frame's weight to (turn / angle)^2");
    t.integer("--gi-filter-iterations", "filter_iterations", [](S& s) -> auto& { return s.filterIterations; }, 0, 6,
              kFrame, "Iterations of the edge-aware a-trous filter of the accumulated GI (0: none)");
    t.real("--gi-filter-sigma", "luminance_sigma", [](S& s) -> auto& { return s.luminanceSigma; }, 0.1, 1000.0,
           kFrame, "The GI filter's luminance edge stop, in standard deviations of a pixel's estimate");
    return t.build();
}

}  // namespace

const OptionTable& temporalGiOptions() {
    static const OptionTable table = makeTable();
    return table;
}

void validate(const TemporalGiSettings& s) { checkRanges(temporalGiOptions(), &s); }

}  // namespace penumbra
