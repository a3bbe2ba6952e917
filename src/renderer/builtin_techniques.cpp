// The built-in modules in the registry: the only place that maps RenderSettings onto each
// technique's own settings, and the rules that span techniques (which GI runs, the RSM's size
// under LPV, the cascades' snap to GI texels).
#include <algorithm>

#include "dsm/dsm_technique.h"
#include "lighting/lighting_technique.h"
#include "lpv/lpv_options.h"
#include "lpv/lpv_technique.h"
#include "renderer/settings_change.h"
#include "renderer/technique_registry.h"
#include "rsm/rsm_options.h"
#include "rsm/rsm_technique.h"
#include "shadow/shadow_technique.h"
#include "sky_light/sky_light_technique.h"
#include "temporal_gi/temporal_gi_technique.h"
#include "voxel/occupancy_technique.h"

namespace penumbra {
namespace {

// The sun's cascades move in whole blocks of the texels that GI reads as one (an RSM texel, or one of
// LPV's down-sampled VPLs), so that those blocks stay on a world-fixed lattice as the camera moves:
// otherwise the RSM's texel centres crawl by fractions of a texel and its light flickers.
uint32_t cascadeSnapTexels(const RenderSettings& s) {
    uint32_t giTexels = 0;
    if (s.gi == GiMode::Rsm) giTexels = s.rsm.resolution;
    if (s.gi == GiMode::Lpv) giTexels = s.lpv.vplResolution;
    return giTexels == 0 ? 1u : std::max(1u, s.shadow.resolution / giTexels);
}

HairCasterSettings hairCasters(const RenderSettings& s) {
    return {s.shadow.depthBiasConstant, s.shadow.depthBiasSlope, s.shadow.pointMode == PointShadowMode::Paraboloid};
}

// Whether the frames are lit by a sky (the lighting module publishes it as names::kSkyLight). An
// unresolved `auto` (a caller that never looked at the lights: tests, the library) is no sky.
bool skyOn(const RenderSettings& s) { return s.lighting.sky.kind != SkyKind::None && s.lighting.sky.kind != SkyKind::Auto; }

// The GI techniques' settings in one string (their option rows' values): the temporal history
// restarts when they change, since it holds another estimator's frames.
std::string giEstimator(const RenderSettings& s) {
    std::string key = std::to_string(int(s.gi)) + ';';  // another GI mode is another estimator
    for (const OptionRow& row : rsmOptions().rows) key += row.value(&s.rsm) + ';';
    for (const OptionRow& row : lpvOptions().rows) key += row.value(&s.lpv) + ';';
    return key;
}

template <class T>
T& as(Technique& t) {
    return static_cast<T&>(t);
}

}  // namespace

bool occupancyUsed(const RenderSettings& s) {
    return (skyOn(s) && s.skyLight.visibility == SkyVisibility::Voxels) ||
           (s.gi == GiMode::Rsm && s.rsm.visibility == RsmVisibility::Voxels) ||
           (s.gi == GiMode::Lpv && s.lpv.geometry == LpvGeometry::Voxels);
}

void addBuiltinTechniques(TechniqueRegistry& r) {
    using S = const RenderSettings&;
    using B = const TechniqueBuild&;
    TechniqueEntry camera{"camera", 10, {}, kPartCamera};
    camera.create = [](B b, S) { return std::make_unique<CameraTechnique>(b); };
    r.add(std::move(camera));

    TechniqueEntry translucency{"translucency", 20, {}, kPartCamera};
    translucency.create = [](B b, S) { return std::make_unique<TranslucencyTechnique>(b); };
    r.add(std::move(translucency));

    TechniqueEntry shadow{"shadow", 30, {"dsm"}, kPartShadow | kPartDsm};
    shadow.create = [](B b, S s) {
        auto t = std::make_unique<ShadowTechnique>(b, s.shadow);
        t->setCascadeSnap(cascadeSnapTexels(s));
        return t;
    };
    shadow.apply = [](Technique& t, S s) {
        as<ShadowTechnique>(t).setSettings(s.shadow);
        as<ShadowTechnique>(t).setCascadeSnap(cascadeSnapTexels(s));
    };
    shadow.adjustParts = kPartShadowFilters;
    shadow.adjust = [](Technique& t, S s, const std::vector<Light>& lights) {
        as<ShadowTechnique>(t).setFilters(s.shadow, lights);
    };
    r.add(std::move(shadow));

    TechniqueEntry dsm{"dsm", 40, {}, kPartShadow | kPartDsm};
    dsm.create = [](B b, S s) { return std::make_unique<DsmTechnique>(b, s.dsm, s.shadow.resolution, hairCasters(s)); };
    dsm.apply = [](Technique& t, S s) { as<DsmTechnique>(t).setCasterSettings(hairCasters(s)); };
    r.add(std::move(dsm));

    TechniqueEntry occupancy{"occupancy", 45, {}, kPartGi};
    occupancy.enabled = occupancyUsed;
    occupancy.create = [](B b, S s) { return std::make_unique<OccupancyTechnique>(b, s.rsm.voxelResolution); };
    r.add(std::move(occupancy));

    TechniqueEntry rsm{"rsm", 50, {"shadow"}, kPartGi};
    rsm.enabled = [](S s) { return s.gi != GiMode::None; };
    rsm.create = [](B b, S s) {
        const bool gather = s.gi == GiMode::Rsm;
        RsmSettings settings = s.rsm;
        if (!gather) settings.resolution = s.lpv.rsmResolution;  // LPV renders the RSM larger and down-samples it
        auto t = std::make_unique<RsmTechnique>(b, settings, gather, s.shadow.resolution);
        if (b.board.require(names::kShadowLayers).shadowed.empty())
            b.warnings.push_back("GI: no directional or spot light casts shadows; no indirect light");
        return t;
    };
    rsm.apply = [](Technique& t, S s) { as<RsmTechnique>(t).setSettings(s.rsm); };
    r.add(std::move(rsm));

    TechniqueEntry lpv{"lpv", 60, {"rsm"}, kPartGi};
    lpv.enabled = [](S s) { return s.gi == GiMode::Lpv; };
    lpv.create = [](B b, S s) { return std::make_unique<LpvTechnique>(b, s.lpv); };
    lpv.apply = [](Technique& t, S s) { as<LpvTechnique>(t).setSettings(s.lpv); };
    r.add(std::move(lpv));

    // Built with the camera, not with the GI: its pipelines outlive a change of GI mode (on lavapipe a
    // module made and dropped at each change left its resident memory growing), and its images are
    // made by the first frame with GI and freed by a frame without.
    TechniqueEntry temporal{"temporal-gi", 70, {}, kPartCamera};
    temporal.enabled = [](S s) { return s.giTemporal; };
    temporal.create = [](B b, S s) {
        auto t = std::make_unique<TemporalGiTechnique>(b, s.temporalGi);
        t->setSettings(s.temporalGi, giEstimator(s));
        return t;
    };
    temporal.apply = [](Technique& t, S s) { as<TemporalGiTechnique>(t).setSettings(s.temporalGi, giEstimator(s)); };
    r.add(std::move(temporal));

    TechniqueEntry sky{"sky-light", 55, {}, kPartCamera};  // before LPV, which bounces its light
    sky.enabled = skyOn;
    sky.create = [](B b, S s) { return std::make_unique<SkyLightTechnique>(b, s.skyLight); };
    sky.apply = [](Technique& t, S s) { as<SkyLightTechnique>(t).setSettings(s.skyLight); };
    sky.resolve = [](RenderSettings& s, const Scene& scene) {
        s.skyLight.visibility = resolveSkyVisibility(s.skyLight, scene.drawnTriangleCount());
    };
    r.add(std::move(sky));

    TechniqueEntry lighting{"lighting", 80, {}, kPartCamera};
    lighting.create = [](B b, S s) { return std::make_unique<LightingTechnique>(b, s.lighting); };
    lighting.apply = [](Technique& t, S s) { as<LightingTechnique>(t).setSettings(s.lighting); };
    r.add(std::move(lighting));
}

}  // namespace penumbra
