// A Renderer with the technique internals the tests read, found by typed lookup
// (Renderer::find<T>): the renderer itself knows only the Technique interface.
#pragma once
#include "dsm/dsm_technique.h"
#include "lighting/lighting_technique.h"
#include "lpv/lpv_technique.h"
#include "renderer/renderer.h"
#include "rsm/rsm_technique.h"
#include "shadow/shadow_technique.h"
#include "voxel/occupancy_technique.h"

namespace penumbra::test {

class TestRenderer : public Renderer {
public:
    using Renderer::Renderer;
    GBufferPass& gbuffer() { return find<CameraTechnique>()->gbuffer(); }
    ShadowMapPass& shadow() { return find<ShadowTechnique>()->pass(); }  // layers, shadow map, mask
    // GI internals (null when that GI mode is off).
    RsmPass* rsm() { return find<RsmTechnique>() ? &find<RsmTechnique>()->pass() : nullptr; }
    RsmGather* rsmGather() { return find<RsmTechnique>() ? find<RsmTechnique>()->gather() : nullptr; }
    RsmFluxSampler* rsmFlux() { return find<RsmTechnique>() ? find<RsmTechnique>()->flux() : nullptr; }
    OccupancyVolume* occupancy() {
        return find<OccupancyTechnique>() ? &find<OccupancyTechnique>()->volume() : nullptr;
    }
    LightPropagationVolume* lpv() { return find<LpvTechnique>() ? &find<LpvTechnique>()->volume() : nullptr; }
    DeepShadowMaps& deepShadows() { return find<DsmTechnique>()->maps(); }
    const CameraTranslucency* translucency() const { return find<TranslucencyTechnique>()->translucency(); }
    const HairGpu* hair() { return sceneHair(gpuScene()); }
};

}  // namespace penumbra::test
