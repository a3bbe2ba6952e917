#include "dsm/dsm_technique.h"

#include "core/gpu_scene.h"

namespace penumbra {

const HairGpu* sceneHair(GpuScene& scene) {
    return scene.attachment<HairGpu>([](vk::CommandContext& cmd, const Scene& s) {
        return s.strands.empty() ? nullptr : std::make_unique<HairGpu>(cmd, s);
    });
}

DsmTechnique::DsmTechnique(const TechniqueBuild& b, const DsmSettings& s, uint32_t shadowResolution,
                           const HairCasterSettings& casters)
    : board_(b.board),
      maps_(b.alloc, b.scene.meshes(), sceneHair(b.scene), s, shadowResolution, b.lights, b.warnings,
            b.core.computeRaster),
      bounds_(b.scene.scene().bounds), countScale_(1.0f / float(s.maxList)) {
    for (uint32_t i = 0; i < b.lights.size(); ++i) covered_.covered.push_back(maps_.covers(i));
    b.board.put(names::kDeepShadowLights, &covered_, this);
    b.board.put(names::kCountAovScale, &countScale_, this);
    const HairGpu* hair = sceneHair(b.scene);
    if (!hair) return;
    // Hair is an opaque caster in the ordinary shadow map of lights without a deep shadow map;
    // blended meshes and hair of lights with one go to their DSM instead.
    for (const Light& l : b.lights)
        if (l.type == LightType::Point && l.castsShadow && casters.paraboloidPoints) {
            b.warnings.push_back("hair casts no shadow in paraboloid point-light maps (use {shadow.point_shadow} cube)");
            break;
        }
    hair_ = std::make_unique<HairShadowPass>(b.alloc, *hair, casters.biasConstant, casters.biasSlope);
    casters_.drawsInto = [this](uint32_t light) { return !covered_.covers(light); };
    casters_.addTo = [this](FrameGraph& g, const ShadowLayers& layers, const std::vector<Light>& lights) {
        hair_->addTo(g, hairLayers(layers, lights));
    };
    b.board.put(names::kShadowCasters, &casters_, this);
}

DsmTechnique::~DsmTechnique() { board_.dropOwner(this); }

void DsmTechnique::setCasterSettings(const HairCasterSettings& s) {
    if (hair_) hair_->setBias(s.biasConstant, s.biasSlope);
}

// The shadow layers hair is drawn into: those of lights without a DSM (paraboloid point-light maps
// bend edges, which the ribbon vertex shader does not: hair casts no shadow there).
std::vector<HairShadowLayer> DsmTechnique::hairLayers(const ShadowLayers& layers,
                                                      const std::vector<Light>& lights) const {
    std::vector<HairShadowLayer> out;
    for (uint32_t k = 0; k < layers.layers.size(); ++k) {
        const ShadowLayerView& l = layers.layers[k];
        if (l.projection.paraboloid || covered_.covers(l.light)) continue;
        out.push_back({k, 1 + k, lightRibbonView(lights[l.light], l.projection)});
    }
    return out;
}

TranslucencyTechnique::TranslucencyTechnique(const TechniqueBuild& b) {
    const HairGpu* hair = sceneHair(b.scene);
    if (b.core.translucency) {
        translucency_ = std::make_unique<CameraTranslucency>(b.alloc, b.scene.meshes(), hair, b.core.width,
                                                             b.core.height, b.core.computeRaster);
        if (!translucency_->active()) translucency_.reset();
    } else if (hair) {
        hair_ = std::make_unique<HairGBufferPass>(b.alloc, *hair);
    }
}

void TranslucencyTechnique::addPasses(const FrameContext& f) {
    const RibbonView view = cameraRibbonView(f.camera.eye, f.uniforms.pixelSpread);
    if (hair_) hair_->addTo(f.graph, view);
    if (translucency_) translucency_->addBuildTo(f.graph, view, f.uniforms.viewProj);
}

}  // namespace penumbra
