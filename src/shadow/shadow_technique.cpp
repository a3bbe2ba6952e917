#include "shadow/shadow_technique.h"

#include "core/gpu_scene.h"

namespace penumbra {

ShadowTechnique::ShadowTechnique(const TechniqueBuild& b, const ShadowSettings& s)
    : board_(b.board), pass_(b.alloc, b.scene.meshes(), s, b.drawLayout) {
    const DeepShadowLights* deep = b.board.get(names::kDeepShadowLights);
    const ShadowCasters* casters = b.board.get(names::kShadowCasters);
    bool extraCasts = false;  // another module rasterizes into the map of a shadowed light
    for (uint32_t i = 0; i < b.lights.size() && casters; ++i)
        extraCasts |= b.lights[i].castsShadow && casters->drawsInto(i);
    pass_.setHardwareCasters(extraCasts);
    pass_.assign(b.lights);
    std::vector<uint32_t> deepLights;
    for (uint32_t i = 0; i < b.lights.size(); ++i)
        if (deep && deep->covers(i)) deepLights.push_back(i);
    pass_.setDeepShadowLights(deepLights);
    layers_.fillGpuLight = [this](uint32_t light, gpu::GpuLight& g) { pass_.fillGpuLight(light, g); };
    publishLayers();
    b.board.put(names::kShadowLayers, &layers_, this);
}

ShadowTechnique::~ShadowTechnique() { board_.dropOwner(this); }

void ShadowTechnique::publishLayers() {
    layers_.resolution = pass_.settings().resolution;
    layers_.layers.clear();
    for (const ShadowLayer& l : pass_.layers()) layers_.layers.push_back({l.light, l.index, l.projection});
    layers_.shadowed.clear();
    for (const ShadowedLight& sl : pass_.layout().shadowed())
        layers_.shadowed.push_back({sl.light, sl.firstLayer, sl.layerCount, sl.kind});
}

void ShadowTechnique::setFilters(const ShadowSettings& s, const std::vector<Light>& lights) {
    pass_.setFilters(s, lights);
    publishLayers();
}

void ShadowTechnique::update(const FrameContext& f) {
    pass_.update(f.lights, f.camera, f.aspect, f.zfar, f.slot, snapTexels_);
    publishLayers();
    layers_.idRequests.clear();  // GI asks again in its update
}

void ShadowTechnique::addPasses(const FrameContext& f) {
    pass_.requestIds(layers_.idRequests);
    std::function<void(FrameGraph&)> extraCasters;
    const ShadowCasters* casters = f.board.get(names::kShadowCasters);
    if (casters && casters->addTo)
        extraCasters = [&](FrameGraph& g) { casters->addTo(g, layers_, f.lights); };
    pass_.addTo(f.graph, 1, extraCasters);
    pass_.addFilterTo(f.graph);
}

}  // namespace penumbra
