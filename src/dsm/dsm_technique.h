// The DSM module as techniques: the deep shadow maps (and hair, which this module owns, as an
// opaque caster in the ordinary shadow maps of the other lights), and the camera's side of hair and
// BLEND surfaces: per-pixel translucency lists composited after lighting, or, with translucency off,
// hair ribbons drawn opaque into the G-buffer.
#pragma once
#include <memory>

#include "core/names.h"
#include "core/technique.h"
#include "dsm/deep_shadow_maps.h"
#include "dsm/hair_passes.h"
#include "dsm/translucency.h"

namespace penumbra {

class GpuScene;

// The scene's hair strands on the GPU, uploaded once per scene (null without strands).
const HairGpu* sceneHair(GpuScene& scene);

// What the ordinary shadow maps hand the hair drawn into them.
struct HairCasterSettings {
    float biasConstant = 0.0f, biasSlope = 0.0f;  // the shadow maps' depth bias
    bool paraboloidPoints = false;  // point lights take paraboloid maps (hair casts no shadow there)
};

// Publishes names::kDeepShadowLights and, with hair, names::kShadowCasters at build (the shadow
// technique is built after it), and names::kCountAovScale.
class DsmTechnique : public Technique {
public:
    DsmTechnique(const TechniqueBuild& b, const DsmSettings& s, uint32_t shadowResolution,
                 const HairCasterSettings& casters);
    ~DsmTechnique() override;
    const char* name() const override { return "dsm"; }
    void update(const FrameContext& f) override { maps_.update(f.lights, bounds_, f.slot); }
    void addPasses(const FrameContext& f) override { maps_.addTo(f.graph); }
    void setCasterSettings(const HairCasterSettings& s);
    DeepShadowMaps& maps() { return maps_; }

private:
    std::vector<HairShadowLayer> hairLayers(const ShadowLayers& layers, const std::vector<Light>& lights) const;
    Blackboard& board_;
    DeepShadowMaps maps_;
    Bounds bounds_;
    DeepShadowLights covered_;
    std::unique_ptr<HairShadowPass> hair_;
    ShadowCasters casters_;
    float countScale_;  // the dsm-lists AOV's tone-map scale
};

// The camera's hair and BLEND surfaces: translucency lists (built after the G-buffer, composited
// over "hdr" after lighting), or opaque hair ribbons in the G-buffer.
class TranslucencyTechnique : public Technique {
public:
    explicit TranslucencyTechnique(const TechniqueBuild& b);
    const char* name() const override { return "translucency"; }
    void addPasses(const FrameContext& f) override;
    void addCompositePasses(const FrameContext& f) override {
        if (translucency_) translucency_->addCompositeTo(f.graph);
    }
    // Null when camera translucency is off or the scene has nothing translucent.
    const CameraTranslucency* translucency() const { return translucency_.get(); }

private:
    std::unique_ptr<HairGBufferPass> hair_;
    std::unique_ptr<CameraTranslucency> translucency_;
};

}  // namespace penumbra
