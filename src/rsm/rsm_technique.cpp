#include "rsm/rsm_technique.h"

#include "core/gpu_scene.h"

namespace penumbra {
namespace {

// RSM layers from the shadow layers: the RSM is the shadow pass's light view with more targets.
// LPV injection and, by default, the RSM gather take only each sun's last, widest cascade: cascades
// see the same surfaces, and a fine one lacks the distant VPLs (RsmSettings::perCascade); with
// perCascade the gather takes every cascade and picks one per receiver, as the seed does.
// Paraboloid layers have no matrix projection to rasterize with.
std::vector<RsmLayerSource> rsmLayersOf(const ShadowLayers& shadow, bool widestCascadeOnly) {
    std::vector<RsmLayerSource> layers;
    const uint32_t res = shadow.resolution;
    for (const ShadowedLightView& sl : shadow.shadowed) {
        const bool cascades = sl.kind == SHADOW_KIND_CASCADES;
        for (uint32_t k = 0; k < sl.layerCount; ++k) {
            const uint32_t index = sl.firstLayer + k;
            const ShadowLayerView& l = shadow.layers[index];
            const bool last = k + 1 == sl.layerCount;
            if (l.projection.paraboloid || (cascades && widestCascadeOnly && !last)) continue;
            RsmLayerSource src{l.light, 1 + index, l.projection, res};
            if (cascades && !widestCascadeOnly) {
                src.cascade = k + 1;
                src.lastCascade = last;
                src.radiusScale = shadow.layers[sl.firstLayer].projection.texelSize / l.projection.texelSize;
            }
            layers.push_back(src);
        }
    }
    return layers;
}

}  // namespace

RsmTechnique::RsmTechnique(const TechniqueBuild& b, const RsmSettings& s, bool gather, uint32_t shadowResolution)
    : board_(b.board), widestCascadeOnly_(!gather || !s.perCascade),
      pass_(b.alloc, b.scene.meshes(), s, shadowResolution) {
    if (gather) gather_ = std::make_unique<RsmGather>(b.alloc, b.cmd, b.core.width, b.core.height, s);
    if (gather) b.board.put(names::kGiChange, &gather_->changeTexel(), this);
    if (gather && s.far == RsmFar::Flux) flux_ = std::make_unique<RsmFluxSampler>(b.alloc, s.resolution, s.seed);
    b.board.put(names::kRsmLayerCount, &layerCount_, this);
}

RsmTechnique::~RsmTechnique() { board_.dropOwner(this); }

// The layers' projections change every frame (cascades follow the camera).
// The shadow pass draws these layers with visibility IDs, which the RSM is resolved from.
void RsmTechnique::update(const FrameContext& f) {
    ShadowLayers& shadow = f.board.require(names::kShadowLayers);
    pass_.setLayers(rsmLayersOf(shadow, widestCascadeOnly_), f.slot);
    shadow.idRequests = pass_.shadowLayers();
    layerCount_ = pass_.layerCount();
}

void RsmTechnique::addPasses(const FrameContext& f) {
    pass_.addTo(f.graph);
    if (flux_ && pass_.layerCount() > 0) flux_->addTo(f.graph, pass_.layerCount());
    if (!gather_) return;
    gather_->addTo(f.graph, pass_.layerCount(), f.slot, f.board.get(names::kGiAccumulation));
    f.graph.contribute(names::kIrradianceContribution, f.graph.image(names::kIrradiance));
}

void RsmTechnique::setSettings(const RsmSettings& s) {
    if (gather_) gather_->setSettings(s);
    if (flux_) flux_->setSeed(s.seed);
}

}  // namespace penumbra
