#include "shadow/shadow_layout.h"

#include <algorithm>
#include <cmath>

namespace penumbra {

static_assert(uint32_t(ShadowFilter::Hard) == SHADOW_FILTER_HARD && uint32_t(ShadowFilter::Pcf) == SHADOW_FILTER_PCF &&
                  uint32_t(ShadowFilter::Pcss) == SHADOW_FILTER_PCSS && uint32_t(ShadowFilter::Vsm) == SHADOW_FILTER_VSM &&
                  uint32_t(ShadowFilter::Evsm) == SHADOW_FILTER_EVSM && uint32_t(ShadowFilter::Msm) == SHADOW_FILTER_MSM,
              "ShadowFilter must match SHADOW_FILTER_* (shaders/shared/types.h)");

namespace {

// 32 points in the unit disc by best-candidate sampling (Mitchell 1991; fixed seed): a progressive
// Poisson-disc set, so its first 16 points are a good 16-tap kernel too.
constexpr float kPoisson[32][2] = {
    {0.0089f, 0.0124f},   {-0.8466f, -0.5311f}, {0.2761f, -0.9527f},  {0.9986f, 0.0330f},   {-0.4154f, 0.9076f},
    {0.4933f, 0.7978f},   {-0.9483f, 0.2735f},  {0.7829f, -0.5769f},  {-0.3354f, -0.8698f}, {-0.4076f, 0.3615f},
    {0.5366f, 0.2758f},   {0.2657f, -0.4447f},  {-0.3896f, -0.3059f}, {0.0185f, 0.6294f},   {0.6130f, -0.1663f},
    {-0.7622f, -0.1075f}, {-0.7420f, 0.6434f},  {0.9085f, 0.4179f},   {-0.1090f, -0.5657f}, {0.1578f, 0.9786f},
    {-0.3329f, 0.0283f},  {0.1897f, 0.3086f},   {0.4822f, -0.6957f},  {0.9541f, -0.2934f},  {0.3312f, 0.0030f},
    {-0.5252f, -0.6054f}, {-0.0342f, -0.9880f}, {-0.1125f, 0.3150f},  {-0.6250f, 0.1566f},  {-0.2781f, 0.6393f},
    {-0.0037f, -0.2819f}, {0.6399f, 0.5477f}};

}  // namespace

bool usesMoments(ShadowFilter f) { return f == ShadowFilter::Vsm || f == ShadowFilter::Evsm || f == ShadowFilter::Msm; }

ShadowLayout::ShadowLayout(const ShadowSettings& settings, const Bounds& sceneBounds)
    : settings_(settings), bounds_(sceneBounds) {}

float ShadowLayout::marginTexels(ShadowFilter filter) const {
    float reach = 0.0f;
    if (filter == ShadowFilter::Pcf) reach = settings_.pcfRadius;
    if (filter == ShadowFilter::Pcss) reach = settings_.pcssMaxRadius;
    if (usesMoments(filter)) reach = float(settings_.blurRadius);
    return std::min(std::ceil(reach) + 2.0f, float(settings_.resolution) / 8.0f);
}

void ShadowLayout::assign(const std::vector<Light>& lights) {
    layers_.clear();
    shadowed_.clear();
    momentLayerOf_.clear();
    momentLayers_ = 0;
    indexOfLight_.assign(lights.size(), -1);
    for (uint32_t i = 0; i < lights.size(); ++i) {
        const Light& l = lights[i];
        if (!l.castsShadow) continue;
        ShadowedLight s;
        s.light = i;
        s.firstLayer = uint32_t(layers_.size());
        s.filter = l.shadowFilter == ShadowFilter::Default ? settings_.filter : l.shadowFilter;
        switch (l.type) {
            case LightType::Directional:
                s.kind = SHADOW_KIND_CASCADES;
                s.layerCount = settings_.cascades.count;
                break;
            case LightType::Spot: s.layerCount = 1; break;
            case LightType::Point:
                const bool cube = settings_.pointMode == PointShadowMode::Cube;
                s.kind = cube ? SHADOW_KIND_CUBE : SHADOW_KIND_PARABOLOID;
                s.layerCount = cube ? 6 : 2;
                break;
        }
        for (uint32_t k = 0; k < s.layerCount; ++k) {
            layers_.push_back({i, k, {}, 0.0f, 0.0f});
            momentLayerOf_.push_back(usesMoments(s.filter) ? momentLayers_++ : SHADOW_NO_MOMENTS);
        }
        indexOfLight_[i] = int(shadowed_.size());
        shadowed_.push_back(s);
    }
}

void ShadowLayout::update(const std::vector<Light>& lights, const Camera& camera, float aspect, float cameraFar,
                          uint32_t cascadeSnapTexels) {
    const uint32_t res = settings_.resolution;
    for (const ShadowedLight& s : shadowed_) {
        const Light& l = lights.at(s.light);
        const float margin = marginTexels(s.filter);
        ShadowLayer* layer = &layers_[s.firstLayer];
        if (s.kind == SHADOW_KIND_CASCADES) {
            const std::vector<Cascade> cascades =
                fitCascades(l.direction, camera, aspect, cameraFar, bounds_, res, settings_.cascades, margin,
                            cascadeSnapTexels);
            for (uint32_t c = 0; c < s.layerCount; ++c) {
                layer[c].projection = cascades[c].projection;
                layer[c].splitNear = cascades[c].splitNear;
                layer[c].splitFar = cascades[c].splitFar;
            }
        } else if (s.kind == SHADOW_KIND_CUBE) {
            const auto faces = cubeFaceProjections(l.position, pointLightRange(l, bounds_), res, margin);
            for (uint32_t f = 0; f < 6; ++f) layer[f].projection = faces[f];
        } else if (s.kind == SHADOW_KIND_PARABOLOID) {
            const auto halves = paraboloidProjections(l.position, l.direction, pointLightRange(l, bounds_), res, margin);
            layer[0].projection = halves[0];
            layer[1].projection = halves[1];
        } else {
            layer[0].projection = spotProjection(l, bounds_, res);
        }
    }
}

std::vector<gpu::GpuShadowLight> ShadowLayout::gpuLights() const {
    std::vector<gpu::GpuShadowLight> out;
    const float sunScale = 2.0f * std::tan(0.5f * settings_.pcssSunAngle * 3.14159265f / 180.0f);
    for (const ShadowedLight& s : shadowed_) {
        gpu::GpuShadowLight g{};
        g.firstLayer = s.firstLayer;
        g.layerCount = s.layerCount;
        g.kind = s.kind;
        g.filterMode = uint32_t(s.filter);
        g.normalOffset = settings_.normalOffset;
        g.penumbraScale = s.kind == SHADOW_KIND_CASCADES ? sunScale : settings_.pcssLightSize;
        out.push_back(g);
    }
    return out;
}

std::vector<gpu::GpuShadowLayer> ShadowLayout::gpuLayers() const {
    std::vector<gpu::GpuShadowLayer> out;
    for (size_t i = 0; i < layers_.size(); ++i) {
        const ShadowLayer& l = layers_[i];
        const ShadowedLight& s = shadowed_[indexOfLight_[l.light]];
        const LightProjection& p = l.projection;
        gpu::GpuShadowLayer g{};
        g.viewProj = p.viewProj;
        g.texelSize = p.texelSize;
        g.zNear = p.zNear;
        g.zFar = p.zFar;
        g.discScale = p.discScale;
        g.splitNear = l.splitNear;
        g.splitFar = l.splitFar;
        g.projection = p.paraboloid ? SHADOW_PROJ_PARABOLOID : p.perspective ? SHADOW_PROJ_PERSPECTIVE : SHADOW_PROJ_ORTHO;
        g.momentLayer = momentLayerOf_[i];
        g.momentFilter = uint32_t(s.filter);
        out.push_back(g);
    }
    return out;
}

gpu::GpuShadowParams ShadowLayout::gpuParams() const {
    gpu::GpuShadowParams g{};
    g.pcfRadius = settings_.pcfRadius;
    g.pcssMaxRadius = settings_.pcssMaxRadius;
    g.cascadeBlend = settings_.cascades.blend;
    g.moments = {settings_.bleedReduction, settings_.evsmPositive, settings_.evsmNegative, settings_.msmBias};
    g.resolution = settings_.resolution;
    g.blurRadius = settings_.blurRadius;
    g.shadowedLights = uint32_t(shadowed_.size());
    for (int i = 0; i < 16; ++i)
        g.poisson[i] = {kPoisson[2 * i][0], kPoisson[2 * i][1], kPoisson[2 * i + 1][0], kPoisson[2 * i + 1][1]};
    return g;
}

}  // namespace penumbra
