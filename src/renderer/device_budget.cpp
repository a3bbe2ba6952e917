#include "renderer/device_budget.h"

#include <algorithm>
#include <bit>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "dsm/dsm_resources.h"
#include "lpv/lpv.h"
#include "raster/raster_mode.h"
#include "core/scene_gpu.h"
#include "core/texture_upload.h"
#include "shadow/shadow_layout.h"
#include "shared/types.h"

namespace penumbra {
namespace {

constexpr double kMiB = 1024.0 * 1024.0;
constexpr uint64_t kVplBytes = sizeof(gpu::GpuVpl);
constexpr uint64_t kHairPointBytes = sizeof(gpu::GpuHairPoint);
constexpr uint64_t kStrandRecordBytes = 16;

std::string plural(size_t count, const std::string& noun) {
    return fmt::format("{} {}{}", count, noun, count == 1 ? "" : "s");
}

// One large resource: its size as a function of the option that scales it (monotone).
struct Demand {
    std::string option;  // "" when no option scales it (the scene's own data)
    uint64_t value = 0, minValue = 1;
    std::string what;
    std::function<uint64_t(uint64_t)> bytes;
    bool storageBuffer = false;  // bound whole through one storage-buffer descriptor
};

std::string mib(uint64_t bytes) { return fmt::format("{:.0f} MiB", double(bytes) / kMiB); }

// The largest value in [minValue, value] whose resource takes at most `cap` bytes, 0 if none does.
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
    std::string msg = fmt::format("{} needs {}, more than {} ({})", d.what, mib(need), limit, mib(limitBytes));
    if (!d.option.empty()) {
        const uint64_t best = largestFitting(d, fits);
        msg = fmt::format("{} {}: {}; {}", d.option, d.value, msg,
                          best ? fmt::format("the largest {} that fits is {}", d.option, best)
                               : fmt::format("no {} fits with the other settings", d.option));
    }
    throw std::invalid_argument(msg);
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

void checkDimension(const std::string& option, uint64_t value, uint64_t limit, const std::string& what) {
    if (value > limit)
        throw std::invalid_argument(fmt::format("{} {}: more than the device's {} ({}); the largest {} that fits is {}",
                                                option, value, what, limit, option, limit));
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
    checkDimension("--width", s.width, lim.imageDimension2D, image);
    checkDimension("--height", s.height, lim.imageDimension2D, image);
    checkDimension("--shadow-res", s.shadow.resolution, lim.imageDimension2D, image);
    checkDimension("--cascades", layers.shadow, lim.imageArrayLayers, "image array layers (shadow layers of all lights)");
    if (s.gi == GiMode::Rsm) checkDimension("--rsm-res", s.rsm.resolution, lim.imageDimension2D, image);
    if (s.gi != GiMode::Lpv) return;
    checkDimension("--lpv-rsm-res", s.lpv.rsmResolution, lim.imageDimension2D, image);
    // Down-sampling runs one work group per VPL (x, y, layer); injection one thread per VPL in groups of 64.
    const uint64_t n = s.lpv.vplResolution, vplLayers = std::max(layers.rsm, 1u);
    checkDimension("--lpv-vpl-res", n, std::min(lim.workGroupCount[0], lim.workGroupCount[1]),
                   "work-group count per dispatch");
    auto vplFits = [&](uint64_t v) {
        const uint64_t bytes = vplLayers * v * v * kVplBytes;
        return bytes <= lim.storageBufferRange && bytes <= lim.allocationSize;
    };
    const uint64_t injectGroups = (vplLayers * n * n + 63) / 64;
    if (injectGroups > lim.workGroupCount[0]) {
        uint64_t best = n;  // the largest that also fits the VPL buffer
        while (best > 1 && ((vplLayers * best * best + 63) / 64 > lim.workGroupCount[0] || !vplFits(best))) --best;
        throw std::invalid_argument(fmt::format(
            "--lpv-vpl-res {}: {} VPLs in {} RSM layer(s) need {} injection work groups, more than the device's "
            "work-group count ({}); the largest --lpv-vpl-res that fits is {}",
            n, vplLayers * n * n, vplLayers, injectGroups, lim.workGroupCount[0], best));
    }
}

std::vector<Demand> frameDemands(const RenderSettings& s, const Scene& scene, const LayerCounts& layers) {
    std::vector<Demand> d;
    const uint64_t w = s.width, h = s.height;
    // The HDR image (RGBA32F) is the largest single image; the rest: G-buffer (albedo 4, normal 8, depth
    // 4; the visibility path: albedo 8 and IDs 4), LDR 4, the HDR read-back 16, GI irradiance 16 (+ lists),
    // shadow mask 4 per shadowed light.
    const uint64_t perPixel = 48 + 4 * uint64_t(layers.shadowedLights) + (s.cameraPath == CameraPath::Visibility ? 8 : 0);
    d.push_back({"--width", w, 1, fmt::format("the {}x{} HDR image (RGBA32F)", w, h),
                 [=](uint64_t v) { return v * h * 16; }});
    d.push_back({"--width", w, 1, fmt::format("the {}x{} frame's other images ({} bytes per pixel)", w, h, perPixel),
                 [=](uint64_t v) { return v * h * perPixel; }});
    const uint64_t shadowLayers = std::max(layers.shadow, 1u), momentLayers = layers.moments;
    d.push_back({"--shadow-res", s.shadow.resolution, 16,
                 fmt::format("the shadow-map array ({} layer(s) of D32)", shadowLayers),
                 [=](uint64_t r) { return r * r * 4 * shadowLayers; }});
    if (s.gi != GiMode::None)  // the RSM's layers of the shadow pass carry visibility IDs (R32_UINT)
        d.push_back({"--shadow-res", s.shadow.resolution, 16,
                     fmt::format("the shadow pass's visibility IDs ({} layer(s) of R32_UINT)", std::max(layers.rsm, 1u)),
                     [=, n = std::max(layers.rsm, 1u)](uint64_t r) { return r * r * 4 * n; }});
    if (momentLayers)
        d.push_back({"--shadow-res", s.shadow.resolution, 16,
                     fmt::format("the moment maps ({} layer(s) of RGBA32F)", momentLayers + 1),
                     [=](uint64_t r) { return r * r * 16 * (momentLayers + 1); }});
    const uint64_t rsmLayers = std::max(layers.rsm, 1u);
    if (s.gi == GiMode::Rsm)
        d.push_back({"--rsm-res", s.rsm.resolution, 8, fmt::format("the RSM ({} layer(s), 16 bytes per texel)", rsmLayers),
                     [=](uint64_t r) { return r * r * 16 * rsmLayers; }});
    if (s.gi == GiMode::Rsm && s.rsm.far == RsmFar::Flux)  // rsm/flux_sums.comp: one buffer, bound whole
        d.push_back({"--rsm-res", s.rsm.resolution, 8,
                     fmt::format("the RSM's flux CDF ({} layer(s), 4 bytes per texel of the map rounded up to a power "
                                 "of two)", rsmLayers),
                     [=](uint64_t r) { const uint64_t n = std::bit_ceil(r); return (n * n + n) * 4 * rsmLayers; }, true});
    if (s.gi == GiMode::Lpv) {
        d.push_back({"--lpv-rsm-res", s.lpv.rsmResolution, 16,
                     fmt::format("the LPV's RSM ({} layer(s), 16 bytes per texel)", rsmLayers),
                     [=](uint64_t r) { return r * r * 16 * rsmLayers; }});
        d.push_back({"--lpv-vpl-res", s.lpv.vplResolution, 1, fmt::format("the VPL buffer ({} layer(s))", rsmLayers),
                     [=](uint64_t n) { return n * n * kVplBytes * rsmLayers; }, true});
        const uint64_t cascades = s.lpv.cascades ? s.lpv.cascades : automaticCascadeCount(scene.bounds);
        d.push_back({"--lpv-res", s.lpv.resolution, 4, fmt::format("each LPV light volume ({} cascade(s))", cascades),
                     [=](uint64_t r) { return r * r * r * cascades * 48 * 3; }, true});
    }
    if (s.dsm.enabled) {
        const uint64_t res = s.dsm.resolution ? s.dsm.resolution : s.shadow.resolution;
        d.push_back({s.dsm.resolution ? "--dsm-res" : "--shadow-res", res, 16,
                     "the deep-shadow-map list heads (one light)", [](uint64_t r) { return r * r * 4 * DSM_HEAD_UINTS; }, true});
        // Separate buffers, the buckets as many as fit one (dsm_resources.cpp): memory, not a descriptor's range.
        d.push_back({s.dsm.resolution ? "--dsm-res" : "--shadow-res", res, 16,
                     "the deep-shadow-map work list and depth buckets (one light)",
                     [](uint64_t r) { return r * r * 4 * (DSM_HEAD_UINTS + DsmResources::kBuckets); }});
    }
    const uint64_t strands = scene.strands.size(), points = scene.strandPoints.size() + 2 * strands;
    if (strands)
        d.push_back({"", 0, 0, fmt::format("the scene's {} hair strands", strands),
                     [=](uint64_t) { return points * kHairPointBytes; }, true});
    const uint64_t vertices = scene.vertices.size() * sizeof(Vertex), indices = scene.indices.size() * 4;
    d.push_back({"", 0, 0, "the scene's vertices", [=](uint64_t) { return vertices; }, true});
    d.push_back({"", 0, 0, "the scene's indices", [=](uint64_t) { return indices; }, true});
    for (const TextureSlot& slot : planTextureTable(scene.textures).slots) {  // an array per size
        const uint64_t bytes = mipChainBytes(slot.width, slot.height) * slot.textures.size();
        d.push_back({"", 0, 0, fmt::format("the scene's {} ({}x{} and their mips)",
                                           plural(slot.textures.size(), "texture"), slot.width, slot.height),
                     [=](uint64_t) { return bytes; }});
    }
    return d;
}

}  // namespace

uint64_t hairBytesPerStrand() {
    return (BuiltinOptions::kHairPointsPerStrand + 2) * kHairPointBytes + kStrandRecordBytes;
}

void checkDeviceBudget(const vk::DeviceLimits& limits, const RenderSettings& settings, const Scene& scene,
                       const std::vector<Light>& lights, bool computeRaster) {
    SceneGpu::checkTextureTable(limits);
    const LayerCounts layers = layerCounts(settings, scene, lights);
    checkDimensions(limits, settings, layers);
    std::vector<Demand> demands = frameDemands(settings, scene, layers);
    if (computeRaster) {
        // Its depth buffer (4 bytes per texel of every layer) and, for the RSM's layers, depth << 32 |
        // ID (8 bytes): storage buffers bound whole (src/raster; 6 cube faces at 2048^2 are 192 MiB).
        const uint64_t shadowLayers = std::max(layers.shadow, 1u), idLayers = std::max(layers.rsm, 1u);
        demands.push_back({"--shadow-res", settings.shadow.resolution, 16,
                           fmt::format("the compute rasterizer's depth buffer ({} layer(s))", shadowLayers),
                           [=](uint64_t r) { return r * r * 4 * shadowLayers; }, true});
        if (settings.gi != GiMode::None)
            demands.push_back({"--shadow-res", settings.shadow.resolution, 16,
                               fmt::format("the compute rasterizer's depth and visibility IDs ({} layer(s), 8 bytes "
                                           "per texel)", idLayers),
                               [=](uint64_t r) { return r * r * 8 * idLayers; }, true});
    }
    checkEach(limits, demands);
}

void checkDeviceBudget(const vk::Context& ctx, const RenderSettings& settings, const Scene& scene,
                       const std::vector<Light>& lights) {
    checkDeviceBudget(ctx.limits(), settings, scene, lights, computeRasterFor(settings.shadow.raster, ctx.properties(),
                                                                      settings.shadow.resolution));
}

void checkStrandBudget(const vk::DeviceLimits& limits, uint32_t strands) {
    const uint64_t pointBytes = (BuiltinOptions::kHairPointsPerStrand + 2) * kHairPointBytes;
    checkEach(limits, {Demand{"--strands", strands, 1,
                              fmt::format("the hair's ribbon points ({} bytes per strand)", pointBytes),
                              [=](uint64_t n) { return n * pointBytes; }, true}});
}

}  // namespace penumbra
