#include "renderer/settings_change.h"

namespace penumbra {
namespace {

// Builds a SettingsOption whose `differs` compares one member path of RenderSettings.
template <class Get>
SettingsOption option(const char* flag, SettingsChange change, uint32_t parts, Get get) {
    return {flag, change, parts, [get](const RenderSettings& a, const RenderSettings& b) { return get(a) != get(b); }};
}

constexpr SettingsChange kFrame = SettingsChange::PerFrame;
constexpr SettingsChange kStructure = SettingsChange::Structure;
constexpr SettingsChange kSizes = SettingsChange::Sizes;

std::vector<SettingsOption> makeTable() {
    using S = const RenderSettings&;
    // The DSM resolution defaults to the shadow map's, so a shadow size also sizes the DSM.
    const uint32_t shadowSized = kPartShadow | kPartGi | kPartDsm;
    return {
        option("--width", kSizes, kPartCamera | kPartGi, [](S s) { return s.width; }),
        option("--height", kSizes, kPartCamera | kPartGi, [](S s) { return s.height; }),
        option("--aov", kFrame, kPartNone, [](S s) { return s.aov; }),
        option("--aov-layer", kFrame, kPartNone, [](S s) { return s.aovLayer; }),
        option("--exposure", kFrame, kPartNone, [](S s) { return s.exposure; }),
        option("--camera-path", kStructure, kPartCamera, [](S s) { return s.cameraPath; }),
        // `--shadow` sets both the opaque filter and deep shadow maps on or off (`pcf,dsm`).
        option("--shadow", kStructure, kPartShadowFilters, [](S s) { return s.shadow.filter; }),
        option("--shadow", kStructure, kPartShadow | kPartGi | kPartDsm, [](S s) { return s.dsm.enabled; }),
        option("--shadow", kStructure, kPartDsm, [](S s) { return s.dsm.opacityMaps; }),
        option("--shadow-res", kSizes, shadowSized, [](S s) { return s.shadow.resolution; }),
        option("--shadow-bias-constant", kFrame, kPartNone, [](S s) { return s.shadow.depthBiasConstant; }),
        option("--shadow-bias-slope", kFrame, kPartNone, [](S s) { return s.shadow.depthBiasSlope; }),
        option("--shadow-normal-offset", kFrame, kPartNone, [](S s) { return s.shadow.normalOffset; }),
        option("--pcf-radius", kFrame, kPartNone, [](S s) { return s.shadow.pcfRadius; }),
        option("--pcss-light-size", kFrame, kPartNone, [](S s) { return s.shadow.pcssLightSize; }),
        option("--pcss-sun-angle", kFrame, kPartNone, [](S s) { return s.shadow.pcssSunAngle; }),
        option("--pcss-max-radius", kFrame, kPartNone, [](S s) { return s.shadow.pcssMaxRadius; }),
        option("--vsm-blur", kFrame, kPartNone, [](S s) { return s.shadow.blurRadius; }),
        option("--vsm-bleed", kFrame, kPartNone, [](S s) { return s.shadow.bleedReduction; }),
        option("--cascades", kSizes, shadowSized, [](S s) { return s.shadow.cascades.count; }),
        option("--csm-lambda", kFrame, kPartNone, [](S s) { return s.shadow.cascades.lambda; }),
        option("--csm-blend", kFrame, kPartNone, [](S s) { return s.shadow.cascades.blend; }),
        option("--csm-distance", kFrame, kPartNone, [](S s) { return s.shadow.cascades.distance; }),
        option("--point-shadow", kStructure, shadowSized, [](S s) { return s.shadow.pointMode; }),
        option("--raster", kStructure, kPartShadow | kPartCamera, [](S s) { return s.shadow.raster; }),
        option("--gi", kStructure, kPartGi, [](S s) { return s.gi; }),
        option("--rsm-res", kSizes, kPartGi, [](S s) { return s.rsm.resolution; }),
        option("--rsm-samples", kFrame, kPartNone, [](S s) { return s.rsm.samples; }),
        option("--rsm-radius", kFrame, kPartNone, [](S s) { return s.rsm.radius; }),
        option("--rsm-seed", kFrame, kPartNone, [](S s) { return s.rsm.seed; }),
        option("--rsm-mode", kStructure, kPartGi, [](S s) { return s.rsm.mode; }),
        option("--rsm-weights", kFrame, kPartNone, [](S s) { return s.rsm.weights; }),
        option("--rsm-vpls", kFrame, kPartNone, [](S s) { return s.rsm.bilinearVpls; }),
        option("--rsm-visibility", kStructure, kPartGi, [](S s) { return s.rsm.visibility; }),
        option("--rsm-voxel-res", kSizes, kPartGi, [](S s) { return s.rsm.voxelResolution; }),
        option("--rsm-radii", kStructure, kPartGi, [](S s) { return s.rsm.radii; }),
        option("--rsm-far", kStructure, kPartGi, [](S s) { return s.rsm.far; }),
        option("--rsm-visibility-rays", kFrame, kPartNone, [](S s) { return s.rsm.visibilityRays; }),
        option("--rsm-visibility-points", kFrame, kPartNone, [](S s) { return s.rsm.visibilityPoints; }),
        option("--gi-temporal", kStructure, kPartCamera, [](S s) { return s.giTemporal; }),
        option("--gi-temporal-alpha", kFrame, kPartNone, [](S s) { return s.giTemporalAlpha; }),
        option("--rsm-lowres", kSizes, kPartGi, [](S s) { return s.rsm.lowResFactor; }),
        option("--rsm-per-cascade", kStructure, kPartGi, [](S s) { return s.rsm.perCascade; }),
        option("--lpv-res", kSizes, kPartGi, [](S s) { return s.lpv.resolution; }),
        // Pass counts: the next frame lists its passes from the new values; nothing is re-created.
        option("--lpv-iterations", kStructure, kPartNone, [](S s) { return s.lpv.iterations; }),
        option("--lpv-cascades", kSizes, kPartGi, [](S s) { return s.lpv.cascades; }),
        option("--lpv-rsm-res", kSizes, kPartGi, [](S s) { return s.lpv.rsmResolution; }),
        option("--lpv-vpl-res", kSizes, kPartGi, [](S s) { return s.lpv.vplResolution; }),
        option("--lpv-occlusion", kFrame, kPartNone, [](S s) { return s.lpv.occlusion; }),
        option("--lpv-camera-geometry", kStructure, kPartNone, [](S s) { return s.lpv.cameraGeometry; }),
        option("--lpv-geometry", kStructure, kPartGi, [](S s) { return int(s.lpv.geometry); }),
        option("--lpv-slice-axis", kFrame, kPartNone, [](S s) { return s.lpv.sliceAxis; }),
        option("--lpv-slice", kFrame, kPartNone, [](S s) { return s.lpv.sliceIndex; }),
        option("--translucency", kStructure, kPartCamera, [](S s) { return s.translucency; }),
        option("--dsm-depth-test", kStructure, kPartDsm, [](S s) { return s.dsm.depthTest; }),
        option("--dsm-lights", kStructure, kPartShadow | kPartDsm, [](S s) { return s.dsm.lights; }),
        option("--dsm-res", kSizes, kPartDsm, [](S s) { return s.dsm.resolution; }),
        option("--dsm-nodes", kSizes, kPartDsm, [](S s) { return s.dsm.poolNodes; }),
        // The DSM's lookup table is written once when its buffers are made: these rebuild it.
        option("--dsm-max-list", kStructure, kPartDsm, [](S s) { return s.dsm.maxList; }),
        option("--dsm-filter", kStructure, kPartDsm, [](S s) { return s.dsm.filterWidth; }),
        option("--dsm-lookup", kStructure, kPartDsm, [](S s) { return s.dsm.lookup; }),
        option("--dsm-bias", kStructure, kPartDsm,
               [](S s) { return std::make_pair(s.dsm.depthBias, s.dsm.normalOffset); }),
    };
}

}  // namespace

const char* settingsChangeName(SettingsChange c) {
    switch (c) {
        case SettingsChange::None: return "none";
        case SettingsChange::PerFrame: return "per-frame";
        case SettingsChange::Structure: return "structure";
        case SettingsChange::Sizes: return "sizes";
    }
    return "?";
}

const std::vector<SettingsOption>& settingsOptionTable() {
    static const std::vector<SettingsOption> table = makeTable();
    return table;
}

SettingsDiff diffSettings(const RenderSettings& before, const RenderSettings& after) {
    SettingsDiff d;
    for (const SettingsOption& o : settingsOptionTable()) {
        if (!o.differs(before, after)) continue;
        d.flags.push_back(o.flag);
        d.change = std::max(d.change, o.change);
        d.parts |= o.parts;
    }
    return d;
}

}  // namespace penumbra
