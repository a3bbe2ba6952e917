#include "dsm/deep_shadow_maps.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <fmt/format.h>

namespace penumbra {
namespace {

// Layer `face` of light l's DSM: the view of its ordinary shadow map (a point light's cube faces
// overlap by the filter's reach, as its cube shadow map's do).
LightProjection dsmProjection(const Light& l, const Bounds& bounds, uint32_t res, uint32_t face,
                              const DsmSettings& s) {
    if (l.type == LightType::Directional) return directionalProjection(l.direction, bounds, res);
    if (l.type == LightType::Spot) return spotProjection(l, bounds, res);
    const float margin = std::ceil(0.5f * s.filterWidth + s.normalOffset) + 2.0f;
    return cubeFaceProjections(l.position, pointLightRange(l, bounds), res, margin)[face];
}

std::vector<DsmLayer> chooseLayers(const std::vector<Light>& lights, const Bounds& bounds, const DsmSettings& s,
                                   uint32_t res) {
    for (uint32_t i : s.lights)
        if (i >= lights.size())
            throw vk::VulkanError(fmt::format("{{dsm.lights}}: light {} does not exist (the scene has {})", i,
                                              lights.size()));
    std::vector<DsmLayer> layers;
    if (!s.enabled) return layers;
    for (uint32_t i = 0; i < lights.size(); ++i) {
        const Light& l = lights[i];
        if (!DsmResources::hasDeepShadowMap(s, l, i)) continue;
        const bool cube = l.type == LightType::Point;
        for (uint32_t face = 0; face < (cube ? 6u : 1u); ++face) {
            const LightProjection p = dsmProjection(l, bounds, res, face, s);
            layers.push_back({i, p, lightRibbonView(l, p), cube, face});
        }
    }
    return layers;
}

std::string count(uint64_t n) {
    if (n >= 1'000'000) return fmt::format("{:.2f}M", double(n) / 1e6);
    if (n >= 10'000) return fmt::format("{:.1f}k", double(n) / 1e3);
    return std::to_string(n);
}

double mib(uint64_t bytes) { return double(bytes) / (1024.0 * 1024.0); }

}  // namespace

DeepShadowMaps::DeepShadowMaps(vk::Allocator& alloc, SceneGpu& scene, const HairGpu* hair, const DsmSettings& settings,
                               uint32_t shadowResolution, const std::vector<Light>& lights,
                               std::vector<std::string>& warnings, bool computeHair)
    : settings_(settings) {
    if (settings.maxList < 1 || settings.maxList > DSM_MAX_LIST_CAP)
        throw vk::VulkanError(fmt::format("{{dsm.max_list}} {}: must be in 1..{}", settings.maxList, DSM_MAX_LIST_CAP));
    uint32_t res = settings.resolution ? settings.resolution : shadowResolution;
    std::vector<DsmLayer> layers = chooseLayers(lights, scene.scene().bounds, settings, res);
    // The shadow maps' resolution, taken by default, halves until the maps' fixed part (heads, work
    // list, depth buckets: 48 bytes a texel) takes at most a quarter of the device's memory: a point
    // light's six faces of 2048^2 need 1.2 GiB, more than lavapipe's half (1 GiB).
    const vk::DeviceLimits& lim = alloc.context().limits();
    const uint32_t wanted = res;
    auto fixed = [&](uint32_t r) { return DsmResources::fixedBytes(uint64_t(r) * r * layers.size(), settings.opacityMaps); };
    res = DsmResources::resolutionFor(settings, res, uint32_t(layers.size()), lim);
    if (res != wanted) {
        warnings.push_back(fmt::format("{{frame.shadow_filter}} {}: {} deep shadow map(s) of {}^2 would take {:.0f} MiB of the "
                                       "device's {:.0f} MiB before any node; {}^2 instead ({{dsm.resolution}} sets it)",
                                       settings.opacityMaps ? "dom" : "dsm", layers.size(), wanted, mib(fixed(wanted)),
                                       mib(alloc.context().limits().deviceMemory), res));
        layers = chooseLayers(lights, scene.scene().bounds, settings, res);
    }
    if (settings.enabled && layers.empty())
        warnings.push_back("{frame.shadow_filter} dsm: no light casts shadows; no deep shadow map");
    const bool blended = std::any_of(scene.scene().materials.begin(), scene.scene().materials.end(),
                                     [](const Material& m) { return m.alphaMode == AlphaMode::Blend; });
    if (settings.opacityMaps && !layers.empty() && blended)
        warnings.push_back("{frame.shadow_filter} dom: deep opacity maps take hair strands only; blended meshes cast no "
                           "shadow from the lights that have one (use {frame.shadow_filter} dsm)");
    if (settings.opacityMaps && !hair) layers.clear();  // nothing to cast: every lookup reads "no map"
    const float domLayer = settings.opacityMaps ? DeepOpacityBuildPass::layerThickness(scene.scene()) : 1.0f;
    res_ = std::make_unique<DsmResources>(alloc, settings, res, std::move(layers), lights.size(), domLayer);
    if (!active()) return;
    if (settings.opacityMaps) {
        opacity_ = std::make_unique<DeepOpacityBuildPass>(alloc, *hair, *res_);
        return;
    }
    build_ = std::make_unique<DeepShadowBuildPass>(alloc, scene, hair, *res_, settings.depthTest, computeHair);
    resolve_ = std::make_unique<DeepShadowResolvePass>(alloc, *res_, settings.lookup == DsmLookup::Links);
}

void DeepShadowMaps::update(const std::vector<Light>& lights, const Bounds& bounds, uint32_t slot) {
    for (DsmLayer& layer : res_->layers) {
        const Light& l = lights.at(layer.light);
        layer.projection = dsmProjection(l, bounds, res_->resolution, layer.face, settings_);
        layer.view = lightRibbonView(l, layer.projection);
    }
    res_->writeTables(settings_, slot);
}

bool DeepShadowMaps::covers(uint32_t light) const {
    return std::any_of(res_->layers.begin(), res_->layers.end(), [&](const DsmLayer& l) { return l.light == light; });
}

void DeepShadowMaps::addTo(FrameGraph& graph) {
    graph.publish("dsm.lights", graph.import(res_->lightTable.current()));
    graph.publish("dsm.heads", graph.import(res_->heads));
    graph.publish("dsm.nodes", graph.import(res_->nodes));
    graph.publish("dsm.side", graph.import(res_->side));
    if (!active()) return;
    if (opacity_) {
        opacity_->addTo(graph);
        return;
    }
    build_->addTo(graph);
    resolve_->addTo(graph);
}

DsmFrameStats DeepShadowMaps::readStats(vk::CommandContext& cmd) const {
    DsmFrameStats s;
    s.maps = res_->layerCount();
    s.resolution = res_->resolution;
    s.capacity = res_->capacity;
    s.deviceLimited = res_->deviceLimited;
    s.maxList = res_->maxList;
    s.poolBytes = res_->poolBytes();
    s.headBytes = active() ? res_->headBytes() : 0;
    if (opacity_) s.opacityLayer = res_->opacityLayer;
    if (!active() || opacity_) return s;
    gpu::DsmStats g;
    const std::vector<uint8_t> bytes = cmd.readBuffer(res_->stats, sizeof(g));
    std::memcpy(&g, bytes.data(), sizeof(g));
    s.fragments = g.fragments;
    s.hidden = g.hidden;
    s.overflow = g.overflow;
    s.kept = g.kept;
    s.beyondMaxList = g.beyondMaxList;
    s.longest = g.longest;
    s.lists = g.lists;
    s.sorted = g.runEntries;
    s.usedBytes = s.sorted * DsmResources::kNodeBytes;  // the runs; the sorted lists reuse their indices
    return s;
}

std::string describeDsm(const DsmFrameStats& s) {
    if (s.maps == 0) return "dsm: no light has a deep shadow map";
    if (s.opacityLayer > 0.0f)
        return fmt::format("dom: {} deep opacity map(s) of {}^2, {} layers of {:.4g} m behind each texel's nearest strand; "
                           "{:.1f} MiB",
                           s.maps, s.resolution, DOM_LAYERS, s.opacityLayer, mib(s.poolBytes + s.headBytes));
    return fmt::format(
        "dsm: {} map(s) of {}^2: {} light-space fragments ({} more hidden behind opaque casters skipped), {} nodes kept "
        "in {} lists (longest {}, {} beyond the {}-node cap dropped, {} of them in depth buckets not sorted); node pool "
        "{:.1f} MiB for {} nodes ({:.1f} MiB used), heads, work list and depth buckets {:.1f} MiB",
        s.maps, s.resolution, count(s.fragments), count(s.hidden), count(s.kept), count(s.lists), s.longest,
        count(s.beyondMaxList), s.maxList, count(s.kept + s.beyondMaxList - s.sorted), mib(s.poolBytes),
        count(s.capacity), mib(s.usedBytes), mib(s.headBytes));
}

std::vector<std::string> dsmWarnings(const DsmFrameStats& s) {
    if (s.overflow == 0) return {};
    return {fmt::format("deep shadow map node pool overflow: {} of {} light-space fragments dropped (pool of {} nodes{})",
                        s.overflow, s.fragments, s.capacity,
                        s.deviceLimited ? ", the most one storage buffer of this device addresses; lower {dsm.resolution}"
                                        : "; raise {dsm.pool_nodes}")};
}

}  // namespace penumbra
