#include "temporal_gi/temporal_gi_technique.h"

#include "core/names.h"

namespace penumbra {

TemporalGiTechnique::TemporalGiTechnique(const TechniqueBuild& b, const TemporalGiSettings& s)
    : settings_(s), sum_(b.alloc, b.core.width, b.core.height), history_(b.alloc, b.core.width, b.core.height) {}

void TemporalGiTechnique::addPasses(const FrameContext& f) {
    const ImageHandle now = sum_.addTo(f.graph);
    if (!now) return;  // no GI this frame: nothing to accumulate
    f.graph.publish(names::kIrradiance, now);
    history_.addTo(f.graph, settings_.alpha);
    f.graph.setContributions(names::kIrradianceContribution, {f.graph.image(names::kIrradiance)});
}

}  // namespace penumbra
