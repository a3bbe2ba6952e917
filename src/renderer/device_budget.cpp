#include "renderer/device_budget.h"

#include <algorithm>
#include <bit>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "dsm/dsm_resources.h"
#include "lpv/lpv.h"
#include "core/raster_mode.h"
#include "core/scene_gpu.h"
#include "core/texture_upload.h"
#include "io/plural.h"
#include "dsm/dsm_options.h"
#include "lighting/lighting_pass.h"
#include "lpv/lpv_options.h"
#include "raster/compute_raster.h"
#include "renderer/render_options.h"
#include "rsm/rsm_flux.h"
#include "rsm/rsm_gather.h"
#include "rsm/rsm_options.h"
#include "rsm/rsm_pass.h"
#include "sky_light/sky_light_options.h"
#include "sky_light/sky_light_technique.h"
#include "temporal_gi/temporal_gi_technique.h"
#include "renderer/technique_registry.h"
#include "voxel/occupancy_volume.h"
#include "shadow/shadow_options.h"
#include "shadow/shadow_layout.h"
#include "shared/types.h"
#include "vk/format_bytes.h"

namespace penumbra {
namespace {

constexpr double kMiB = 1024.0 * 1024.0;
constexpr uint64_t kHairPointBytes = sizeof(gpu::GpuHairPoint);
constexpr uint64_t kStrandRecordBytes = sizeof(gpu::GpuStrand);

// The options a refusal names and can suggest a value of (None: the scene's own data).
enum class Knob {
    None, Width, Height, ShadowRes, Cascades, RsmRes, VoxelRes, LpvRsmRes, LpvVplRes, LpvRes, DsmRes, DsmNodes, SkyMapRes
};

struct KnobRow {
    const OptionRow* row = nullptr;
    std::function<void(RenderSettings&, uint64_t)> set;
};

KnobRow knobRow(Knob k) {
    using R = RenderSettings;
    auto row = [](const OptionTable& t, const std::string& flag) { return t.find(flag); };
    const OptionTable &frame = frameOptionTable(), &shadow = shadowOptions(), &rsm = rsmOptions(),
                      &lpv = lpvOptions(), &dsm = dsmOptions();
    using Sh = ShadowSettings;
    using L = LpvSettings;
    switch (k) {
    case Knob::Width:
        return {row(frame, frame.flagOf<R>([](R& x) -> auto& { return x.width; })),
                [](R& s, uint64_t v) { s.width = uint32_t(v); }};
    case Knob::Height:
        return {row(frame, frame.flagOf<R>([](R& x) -> auto& { return x.height; })),
                [](R& s, uint64_t v) { s.height = uint32_t(v); }};
    case Knob::ShadowRes:
        return {row(shadow, shadow.flagOf<Sh>([](Sh& x) -> auto& { return x.resolution; })),
                [](R& s, uint64_t v) { s.shadow.resolution = uint32_t(v); }};
    case Knob::Cascades:
        return {row(shadow, shadow.flagOf<Sh>([](Sh& x) -> auto& { return x.cascades.count; })),
                [](R& s, uint64_t v) { s.shadow.cascades.count = uint32_t(v); }};
    case Knob::RsmRes:
        return {row(rsm, rsm.flagOf<RsmSettings>([](RsmSettings& x) -> auto& { return x.resolution; })),
                [](R& s, uint64_t v) { s.rsm.resolution = uint32_t(v); }};
    case Knob::VoxelRes:
        return {row(rsm, rsm.flagOf<RsmSettings>([](RsmSettings& x) -> auto& { return x.voxelResolution; })),
                [](R& s, uint64_t v) { s.rsm.voxelResolution = uint32_t(v); }};
    case Knob::LpvRsmRes:
        return {row(lpv, lpv.flagOf<L>([](L& x) -> auto& { return x.rsmResolution; })),
                [](R& s, uint64_t v) { s.lpv.rsmResolution = uint32_t(v); }};
    case Knob::LpvVplRes:
        return {row(lpv, lpv.flagOf<L>([](L& x) -> auto& { return x.vplResolution; })),
                [](R& s, uint64_t v) { s.lpv.vplResolution = uint32_t(v); }};
    case Knob::LpvRes:
        return {row(lpv, lpv.flagOf<L>([](L& x) -> auto& { return x.resolution; })),
                [](R& s, uint64_t v) { s.lpv.resolution = uint32_t(v); }};
    case Knob::DsmRes:
        return {row(dsm, dsm.flagOf<DsmSettings>([](DsmSettings& x) -> auto& { return x.resolution; })),
                [](R& s, uint64_t v) { s.dsm.resolution = uint32_t(v); }};
    case Knob::DsmNodes:
        return {row(dsm, dsm.flagOf<DsmSettings>([](DsmSettings& x) -> auto& { return x.poolNodes; })),
                [](R& s, uint64_t v) { s.dsm.poolNodes = v; }};
    case Knob::SkyMapRes: {
        const OptionTable& sky = skyLightOptions();
        using K = SkyLightSettings;
        return {row(sky, sky.flagOf<K>([](K& x) -> auto& { return x.mapResolution; })),
                [](R& s, uint64_t v) { s.skyLight.mapResolution = uint32_t(v); }};
    }
    case Knob::None: break;
    }
    return {};
}

std::string flagOf(Knob k) { return k == Knob::None ? std::string() : knobRow(k).row->flag; }

// A refusal before its advice: what does not fit, the option that scales it, and the largest value
// that fits this one resource (an upper bound for the value the advice names).
struct BudgetRefusal : std::invalid_argument {
    Knob knob;
    uint64_t value, bound;
    BudgetRefusal(const std::string& what, Knob k, uint64_t v, uint64_t b)
        : std::invalid_argument(what), knob(k), value(v), bound(b) {}
};

// One large resource: its size as a function of the option that scales it (monotone).
struct Demand {
    Knob knob = Knob::None;
    uint64_t value = 0, minValue = 1;
    std::string what;
    std::function<uint64_t(uint64_t)> bytes;
    bool storageBuffer = false;  // bound whole through one storage-buffer descriptor
    std::string option = flagOf(knob);  // set explicitly where no RenderSettings row scales it
};

std::string mib(uint64_t bytes) { return fmt::format("{:.0f} MiB", double(bytes) / kMiB); }

// Sizes that round to the same MiB are told in bytes.
std::pair<std::string, std::string> sizes(uint64_t need, uint64_t limit) {
    if (mib(need) != mib(limit)) return {mib(need), mib(limit)};
    return {fmt::format("{} bytes", need), fmt::format("{} bytes", limit)};
}

// The largest value in [minValue, value] for which `fits` holds, 0 if none does.
uint64_t largestFitting(const Demand& d, const std::function<bool(uint64_t)>& fits) {
    if (!fits(d.minValue)) return 0;
    uint64_t lo = d.minValue, hi = d.value;  // fits(lo), !fits(hi)
    while (hi - lo > 1) {
        const uint64_t mid = lo + (hi - lo) / 2;
        (fits(mid) ? lo : hi) = mid;
    }
    return lo;
}

[[noreturn]] void refuse(const Demand& d, uint64_t need, const std::string& limit, uint64_t limitBytes,
                         const std::function<bool(uint64_t)>& fits) {
    const auto [needText, limitText] = sizes(need, limitBytes);
    std::string msg = fmt::format("{} needs {}, more than {} ({})", d.what, needText, limit, limitText);
    if (!d.option.empty()) msg = fmt::format("{} {}: {}", d.option, d.value, msg);
    throw BudgetRefusal(msg, d.knob, d.value, d.option.empty() ? 0 : largestFitting(d, fits));
}

// Whether the resource alone fits the per-resource limits at `value`.
bool fitsAlone(const vk::DeviceLimits& lim, const Demand& d, uint64_t value) {
    const uint64_t b = d.bytes(value);
    return b <= lim.allocationSize && (!d.storageBuffer || b <= lim.storageBufferRange);
}

void checkEach(const vk::DeviceLimits& lim, const std::vector<Demand>& demands) {
    for (const Demand& d : demands) {
        const uint64_t need = d.bytes(d.value);
        auto fits = [&](uint64_t v) { return fitsAlone(lim, d, v); };
        if (need > lim.allocationSize) refuse(d, need, "the device's largest allocation", lim.allocationSize, fits);
        if (d.storageBuffer && need > lim.storageBufferRange)
            refuse(d, need, "the device's storage-buffer range", lim.storageBufferRange, fits);
    }
    // Together they must leave the device some memory; the largest one is named.
    const uint64_t budget = lim.deviceMemory / 10 * 9;
    uint64_t total = 0;
    const Demand* largest = nullptr;
    for (const Demand& d : demands) {
        total += d.bytes(d.value);
        if (!largest || d.bytes(d.value) > largest->bytes(largest->value)) largest = &d;
    }
    if (largest && total > budget) {
        const uint64_t others = total - largest->bytes(largest->value);
        refuse(*largest, total, "90% of the device's memory", budget, [&](uint64_t v) {
            return others + largest->bytes(v) <= budget && fitsAlone(lim, *largest, v);
        });
    }
}

void checkDimension(Knob knob, uint64_t value, uint64_t limit, const std::string& what) {
    if (value > limit)
        throw BudgetRefusal(fmt::format("{} {}: more than the device's {} ({})", flagOf(knob), value, what, limit),
                            knob, value, limit);
}

struct LayerCounts {
    uint32_t shadow = 0, moments = 0, rsm = 0, shadowedLights = 0;
};

// The shadow layers (ShadowLayout) and the RSM layers the renderer takes from them: a sun's widest
// cascade (or every cascade with --rsm-per-cascade and RSM GI), every spot and cube face; no paraboloid.
LayerCounts layerCounts(const RenderSettings& s, const Scene& scene, const std::vector<Light>& lights) {
    ShadowLayout layout(s.shadow, scene.bounds);
    layout.assign(lights);
    LayerCounts c;
    c.shadow = uint32_t(layout.layers().size());
    c.moments = layout.momentLayerCount();
    c.shadowedLights = uint32_t(layout.shadowed().size());
    const bool everyCascade = s.gi == GiMode::Rsm && s.rsm.perCascade;
    for (const ShadowedLight& l : layout.shadowed()) {
        const Light& light = lights[l.light];
        if (light.type == LightType::Point) c.rsm += s.shadow.pointMode == PointShadowMode::Cube ? l.layerCount : 0;
        else if (light.type == LightType::Directional) c.rsm += everyCascade ? l.layerCount : 1;
        else c.rsm += 1;
    }
    return c;
}

void checkDimensions(const vk::DeviceLimits& lim, const RenderSettings& s, const LayerCounts& layers) {
    const std::string image = "largest 2D image side";
    checkDimension(Knob::Width, s.width, lim.imageDimension2D, image);
    checkDimension(Knob::Height, s.height, lim.imageDimension2D, image);
    checkDimension(Knob::ShadowRes, s.shadow.resolution, lim.imageDimension2D, image);
    if (layers.shadow > lim.imageArrayLayers)
        throw BudgetRefusal(fmt::format("{} shadow layers of all lights: more than the device's image array layers ({})",
                                        layers.shadow, lim.imageArrayLayers),
                            Knob::Cascades, s.shadow.cascades.count, s.shadow.cascades.count - 1);
    if (s.gi == GiMode::Rsm) checkDimension(Knob::RsmRes, s.rsm.resolution, lim.imageDimension2D, image);
    if (s.gi != GiMode::Lpv) return;
    checkDimension(Knob::LpvRsmRes, s.lpv.rsmResolution, lim.imageDimension2D, image);
    // Down-sampling runs one work group per VPL (x, y, layer); injection one thread per VPL in groups of 64.
    const uint64_t n = s.lpv.vplResolution, vplLayers = std::max(layers.rsm, 1u);
    checkDimension(Knob::LpvVplRes, n, std::min(lim.workGroupCount[0], lim.workGroupCount[1]),
                   "work-group count per dispatch");
    auto groups = [&](uint64_t v) { return (vplLayers * v * v + 63) / 64; };
    if (groups(n) > lim.workGroupCount[0]) {
        uint64_t best = n;
        while (best > 1 && groups(best) > lim.workGroupCount[0]) --best;
        throw BudgetRefusal(fmt::format("{} {}: {} VPLs in {} RSM layer(s) need {} injection work groups, more than "
                                        "the device's work-group count ({})",
                                        flagOf(Knob::LpvVplRes), n, vplLayers * n * n, vplLayers, groups(n),
                                        lim.workGroupCount[0]),
                            Knob::LpvVplRes, n, best);
    }
}

void addDsmDemands(std::vector<Demand>& d, const vk::DeviceLimits& lim, const RenderSettings& s,
                   const std::vector<Light>& lights) {
    const uint32_t maps = DsmResources::layerCountFor(s.dsm, lights);
    if (!maps) return;
    const Knob knob = s.dsm.resolution ? Knob::DsmRes : Knob::ShadowRes;
    const uint64_t value = s.dsm.resolution ? s.dsm.resolution : s.shadow.resolution;
    const bool dom = s.dsm.opacityMaps;
    const DsmSettings dsm = s.dsm;
    // The texels of all maps at option value `v` (the automatic resolution may halve the shadow maps').
    auto texels = [=](uint64_t v) {
        DsmSettings at = dsm;
        if (at.resolution) at.resolution = uint32_t(v);
        const uint64_t r = DsmResources::resolutionFor(at, uint32_t(v), maps, lim);
        return r * r * maps;
    };
    const std::string of = fmt::format("({} map(s))", maps);
    d.push_back({knob, value, 16, "the deep-shadow-map list heads " + of,
                 [=](uint64_t v) { return DsmResources::headBytes(texels(v), dom); }, true});
    d.push_back({knob, value, 16, "the deep-shadow-map work list " + of,
                 [=](uint64_t v) { return DsmResources::workBytes(texels(v), dom); }, true});
    if (!dom)
        d.push_back({knob, value, 16, "the deep-shadow-map depth buckets " + of, [=](uint64_t v) {
                         const uint64_t t = texels(v);
                         return DsmResources::bucketBytes(t, DsmResources::bucketCountFor(t, lim.storageBufferRange));
                     }});
    const Knob poolKnob = s.dsm.poolNodes ? Knob::DsmNodes : knob;
    const uint64_t poolValue = s.dsm.poolNodes ? s.dsm.poolNodes : value;
    auto capacity = [=](uint64_t v) {
        DsmSettings at = dsm;
        if (at.poolNodes) at.poolNodes = v;
        return DsmResources::poolCapacity(at, texels(at.poolNodes ? value : v), lim);
    };
    d.push_back({poolKnob, poolValue, 1, "the deep-shadow-map node pool " + of,
                 [=](uint64_t v) { return DsmResources::nodeBufferBytes(capacity(v)); }, true});
    if (!dom)  // the side entry and the build's run entry per node: separate buffers
        d.push_back({poolKnob, poolValue, 1, "the deep-shadow-map node keys and runs " + of, [=](uint64_t v) {
                         return capacity(v) * (DsmResources::kNodeBytes - DsmResources::nodeBufferBytes(1));
                     }});
}

void addLpvDemands(std::vector<Demand>& d, const RenderSettings& s, const Scene& scene, uint32_t rsmLayers) {
    d.push_back({Knob::LpvRsmRes, s.lpv.rsmResolution, 16,
                 fmt::format("the LPV's RSM ({} layer(s), 16 bytes per texel)", rsmLayers),
                 [=](uint64_t r) { return r * r * 16 * rsmLayers; }});
    d.push_back({Knob::LpvVplRes, s.lpv.vplResolution, 1, fmt::format("the VPL buffer ({} layer(s))", rsmLayers),
                 [=](uint64_t n) { return lpvVplBytes(n, rsmLayers); }, true});
    if (s.lighting.sky.kind != SkyKind::None) {  // the sky's bounce: a VPL per camera surfel, after the RSM's
        const uint64_t step = std::max(s.lpv.cameraGeometryStep, 1u), h = s.height;
        d.push_back({Knob::Width, s.width, 1, "the LPV's sky VPLs (one per camera surfel)", [=](uint64_t w) {
                         return ((w + step - 1) / step) * ((h + step - 1) / step) * sizeof(gpu::GpuVpl);
                     }});
    }
    const uint64_t cascades = s.lpv.cascades ? s.lpv.cascades : automaticCascadeCount(scene.bounds);
    const std::string of = fmt::format("({} cascade(s))", cascades);
    for (const char* which : {"the LPV's light volume A ", "the LPV's light volume B "})
        d.push_back({Knob::LpvRes, s.lpv.resolution, 4, which + of,
                     [=](uint64_t r) { return lpvLightVolumeBytes(r, cascades); }, true});
    d.push_back({Knob::LpvRes, s.lpv.resolution, 4, "the LPV's light sum (near and far) " + of,
                 [=](uint64_t r) { return 2 * lpvLightVolumeBytes(r, cascades); }, true});
    if (s.giTemporal) {  // the temporal gradients: last frame's light sum kept, and the change image
        d.push_back({Knob::LpvRes, s.lpv.resolution, 4, "the LPV's kept light sum (temporal gradients) " + of,
                     [=](uint64_t r) { return 2 * lpvLightVolumeBytes(r, cascades); }, true});
        const uint64_t h = s.height;
        d.push_back({Knob::Width, s.width, 1, fmt::format("the LPV's temporal gradients ({}x{})", s.width, h),
                     [=](uint64_t w) { return lpvGradientBytes(w, h); }});
    }
    const int geometryVolumes = s.lpv.geometry == LpvGeometry::Voxels ? 2 : 1;  // geometry, and the voxels' faces
    for (int i = 0; i < geometryVolumes; ++i)
        d.push_back({Knob::LpvRes, s.lpv.resolution, 4, "an LPV geometry volume " + of,
                     [=](uint64_t r) { return lpvGeometryVolumeBytes(r, cascades); }, true});
}

std::vector<Demand> frameDemands(const vk::DeviceLimits& lim, const RenderSettings& requested, const Scene& scene,
                                 const std::vector<Light>& lights, const LayerCounts& layers, bool computeRaster) {
    const RenderSettings s = resolveForScene(requested, scene);  // what the renderer will build
    std::vector<Demand> d;
    const uint64_t w = s.width, h = s.height;
    // The HDR image (RGBA32F) is the largest single image; the rest: G-buffer (albedo 4, normal 8, depth
    // 4; the visibility path: albedo 8 and IDs 4), LDR 4, the HDR read-back 16, GI irradiance 16 (+ lists),
    // shadow mask 4 per shadowed light.
    const uint64_t gbuffer = 4 + 8 + 4, ldr = 4, hdrReadBack = 16, irradiance = 16;
    const uint64_t perPixel = gbuffer + ldr + hdrReadBack + irradiance + 4 * uint64_t(layers.shadowedLights) +
                              (s.cameraPath == CameraPath::Visibility ? 8 : 0);
    d.push_back({Knob::Width, w, 1, fmt::format("the {}x{} HDR image (RGBA32F)", w, h),
                 [=](uint64_t v) { return v * h * vk::texelBytes(LightingPass::kHdrFormat); }});
    d.push_back({Knob::Width, w, 1, fmt::format("the {}x{} frame's other images ({} bytes per pixel)", w, h, perPixel),
                 [=](uint64_t v) { return v * h * perPixel; }});
    if (s.gi == GiMode::Rsm && s.rsm.mode == RsmMode::Interpolated)
        d.push_back({Knob::Width, w, 1, fmt::format("the RSM gather's pixel list ({}x{})", w, h),
                     [=](uint64_t v) { return RsmGather::pixelListBytes(uint32_t(v), uint32_t(h)); }, true});
    if (s.gi == GiMode::Rsm && s.rsm.mode == RsmMode::Interpolated && s.giTemporal)
        d.push_back({Knob::Width, w, 1, fmt::format("the RSM's temporal gradients ({}x{})", w, h), [=](uint64_t v) {
                         return RsmGather::gradientBytes(uint32_t(v), uint32_t(h), s.rsm.lowResFactor);
                     }});
    if (s.lighting.sky.kind != SkyKind::None)  // an unresolved auto counted as a sky: the estimate stays an upper bound
        d.push_back({Knob::Width, w, 1, fmt::format("the sky light's {}x{} visibility and irradiance", w, h),
                     [=](uint64_t v) { return SkyLightTechnique::bytes(v, h, s.skyLight.traceStep); }});
    if (s.lighting.sky.kind != SkyKind::None && s.skyLight.visibility == SkyVisibility::Maps) {
        const uint32_t maps = s.skyLight.mapCount;
        d.push_back({Knob::SkyMapRes, s.skyLight.mapResolution, 64,
                     fmt::format("the sky visibility maps ({} layers of R32F)", maps),
                     [=](uint64_t r) { return SkyLightTechnique::mapBytes(r, maps); }});
        d.push_back({Knob::SkyMapRes, s.skyLight.mapResolution, 64,
                     fmt::format("the compute rasterizer's depth buffer for the sky maps ({} layers)", maps),
                     [=](uint64_t r) { return ComputeRaster::depthBytes(r * r, maps); }, true});
    }
    if (s.giTemporal && s.gi != GiMode::None)
        d.push_back({Knob::Width, w, 1, fmt::format("the GI history and filter ({}x{})", w, h),
                     [=](uint64_t v) { return TemporalGiTechnique::bytes(v, h); }});
    const uint64_t shadowLayers = std::max(layers.shadow, 1u), momentLayers = layers.moments;
    const uint64_t rsmLayers = std::max(layers.rsm, 1u);
    d.push_back({Knob::ShadowRes, s.shadow.resolution, 16,
                 fmt::format("the shadow-map array ({} layer(s) of D32)", shadowLayers),
                 [=](uint64_t r) { return r * r * vk::texelBytes(VK_FORMAT_D32_SFLOAT) * shadowLayers; }});
    if (s.gi != GiMode::None)  // the RSM's layers of the shadow pass carry visibility IDs (R32_UINT)
        d.push_back({Knob::ShadowRes, s.shadow.resolution, 16,
                     fmt::format("the shadow pass's visibility IDs ({} layer(s) of R32_UINT)", rsmLayers),
                     [=](uint64_t r) { return r * r * vk::texelBytes(VK_FORMAT_R32_UINT) * rsmLayers; }});
    if (momentLayers)
        d.push_back({Knob::ShadowRes, s.shadow.resolution, 16,
                     fmt::format("the moment maps ({} layer(s) of RGBA32F)", momentLayers + 1),
                     [=](uint64_t r) {
                         return r * r * vk::texelBytes(VK_FORMAT_R32G32B32A32_SFLOAT) * (momentLayers + 1);
                     }});
    if (computeRaster) {
        d.push_back({Knob::ShadowRes, s.shadow.resolution, 16,
                     fmt::format("the compute rasterizer's depth buffer ({} layer(s))", shadowLayers),
                     [=](uint64_t r) { return ComputeRaster::depthBytes(r * r, uint32_t(shadowLayers)); }, true});
        if (s.gi != GiMode::None)
            d.push_back({Knob::ShadowRes, s.shadow.resolution, 16,
                         fmt::format("the compute rasterizer's depth and visibility IDs ({} layer(s))", rsmLayers),
                         [=](uint64_t r) { return ComputeRaster::depthIdBytes(r * r, uint32_t(rsmLayers)); }, true});
    }
    if (s.gi == GiMode::Rsm)
        d.push_back({Knob::RsmRes, s.rsm.resolution, 8,
                     fmt::format("the RSM ({} layer(s), {} bytes per texel)", rsmLayers, RsmPass::texelBytes()),
                     [=](uint64_t r) { return r * r * RsmPass::texelBytes() * rsmLayers; }});
    if (s.gi == GiMode::Rsm && s.rsm.far == RsmFar::Flux)
        d.push_back({Knob::RsmRes, s.rsm.resolution, 8, fmt::format("the RSM's flux CDF ({} layer(s))", rsmLayers),
                     [=](uint64_t r) { return RsmFluxSampler::cdfBytes(uint32_t(r), uint32_t(rsmLayers)); }, true});
    if (s.gi == GiMode::Lpv) addLpvDemands(d, s, scene, uint32_t(rsmLayers));
    if (occupancyUsed(s) || s.lighting.sky.kind == SkyKind::Auto) {  // an unresolved auto: an upper bound
        const bool facing = hasSingleSidedSurfaces(scene);  // the sky's facing bits, 4 a voxel
        const Bounds bounds = scene.bounds;
        d.push_back({Knob::VoxelRes, s.rsm.voxelResolution, 8,
                     facing ? "the occupancy volume (its voxel bits and the sky's facing bits)" : "the occupancy volume",
                     [=](uint64_t r) { return OccupancyVolume::bytes(bounds, uint32_t(r), facing); }, true});
    }
    addDsmDemands(d, lim, s, lights);
    const uint64_t strands = scene.strands.size(), points = scene.strandPoints.size() + 2 * strands;
    if (strands)
        d.push_back({Knob::None, 0, 0, fmt::format("the scene's {} hair strands", strands),
                     [=](uint64_t) { return points * kHairPointBytes; }, true});
    const uint64_t vertices = scene.vertices.size() * sizeof(Vertex);
    const uint64_t indices = scene.indices.size() * sizeof(scene.indices.front());
    d.push_back({Knob::None, 0, 0, "the scene's vertices", [=](uint64_t) { return vertices; }, true});
    d.push_back({Knob::None, 0, 0, "the scene's indices", [=](uint64_t) { return indices; }, true});
    for (const TextureSlot& slot : planTextureTable(scene.textures).slots) {  // an array per size
        const uint64_t bytes = mipChainBytes(slot.width, slot.height) * slot.textures.size();
        d.push_back({Knob::None, 0, 0, fmt::format("the scene's {} ({}x{} and their mips)",
                                                   plural(slot.textures.size(), "texture"), slot.width, slot.height),
                     [=](uint64_t) { return bytes; }});
    }
    return d;
}

using ComputeRasterAt = std::function<bool(const RenderSettings&)>;

// Every check once; throws BudgetRefusal without advice.
void checkOnce(const vk::DeviceLimits& limits, const RenderSettings& settings, const Scene& scene,
               const std::vector<Light>& lights, const ComputeRasterAt& computeRaster) {
    const LayerCounts layers = layerCounts(settings, scene, lights);
    checkDimensions(limits, settings, layers);
    checkEach(limits, frameDemands(limits, settings, scene, lights, layers, computeRaster(settings)));
}

// The advice for a refusal: the largest value the option accepts (its range, and every rule between
// settings) with which the whole budget check passes, searched down from the refused resource's own
// bound; or, if none does, what then refuses at the option's smallest value.
std::string advice(const BudgetRefusal& refusal, const vk::DeviceLimits& limits, const RenderSettings& settings,
                   const Scene& scene, const std::vector<Light>& lights, const ComputeRasterAt& computeRaster) {
    const KnobRow knob = knobRow(refusal.knob);
    const uint64_t smallest = uint64_t(std::max(knob.row->min, 1.0));
    auto refusalAt = [&](uint64_t v) -> std::optional<std::string> {
        RenderSettings at = settings;
        knob.set(at, v);
        try {
            validateSettings(at);
            checkOnce(limits, at, scene, lights, computeRaster);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::nullopt;
    };
    const uint64_t start = refusal.bound ? std::min(refusal.bound, refusal.value - 1) : refusal.value - 1;
    for (uint64_t v = start; v >= smallest && v > 0; --v)
        if (!refusalAt(v)) return fmt::format("the largest {} that fits is {}", knob.row->flag, v);
    const std::optional<std::string> atSmallest = refusalAt(smallest);
    return fmt::format("no {} fits with the other settings; at {} {}: {}", knob.row->flag, knob.row->flag, smallest,
                       atSmallest.value_or("?"));
}

void checkWithAdvice(const vk::DeviceLimits& limits, const RenderSettings& settings, const Scene& scene,
                     const std::vector<Light>& lights, const ComputeRasterAt& computeRaster) {
    SceneGpu::checkTextureTable(limits);
    try {
        checkOnce(limits, settings, scene, lights, computeRaster);
    } catch (const BudgetRefusal& r) {
        if (r.knob == Knob::None) throw std::invalid_argument(r.what());
        throw std::invalid_argument(fmt::format("{}; {}", r.what(), advice(r, limits, settings, scene, lights,
                                                                            computeRaster)));
    }
}

}  // namespace

uint64_t hairBytesPerStrand() {
    return (BuiltinOptions::kHairPointsPerStrand + 2) * kHairPointBytes + kStrandRecordBytes;
}

void checkDeviceBudget(const vk::DeviceLimits& limits, const RenderSettings& settings, const Scene& scene,
                       const std::vector<Light>& lights, bool computeRaster) {
    checkWithAdvice(limits, settings, scene, lights, [=](const RenderSettings&) { return computeRaster; });
}

void checkDeviceBudget(const vk::Context& ctx, const RenderSettings& settings, const Scene& scene,
                       const std::vector<Light>& lights) {
    checkWithAdvice(ctx.limits(), settings, scene, lights, [&](const RenderSettings& s) {
        return computeRasterFor(s.shadow.raster, ctx.properties(), s.shadow.resolution);
    });
}

void checkStrandBudget(const vk::DeviceLimits& limits, uint32_t strands) {
    const uint64_t pointBytes = (BuiltinOptions::kHairPointsPerStrand + 2) * kHairPointBytes;
    Demand ribbons{Knob::None, strands, 1, fmt::format("the hair's ribbon points ({} bytes per strand)", pointBytes),
                   [=](uint64_t n) { return n * pointBytes; }, true, "{inputs.strands}"};
    try {
        checkEach(limits, {ribbons});
    } catch (const BudgetRefusal& r) {  // the only demand: its own bound is the answer
        throw std::invalid_argument(r.bound ? fmt::format("{}; the largest {} that fits is {}", r.what(), ribbons.option,
                                                          r.bound)
                                            : fmt::format("{}; no {} fits", r.what(), ribbons.option));
    }
}

}  // namespace penumbra
