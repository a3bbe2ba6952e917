#include <cstring>
#include <utility>

#include "api/convert.h"

namespace penumbra::api {
namespace {

// One copy between a public and an internal field (enums by value: their enumerators are asserted
// to match below).
struct Assign {
    template <class To, class From>
    void operator()(To& to, const From& from) const { to = static_cast<To>(from); }
    void operator()(Vec3& to, const glm::vec3& from) const { to = {from.x, from.y, from.z}; }
    void operator()(glm::vec3& to, const Vec3& from) const { to = {from.x, from.y, from.z}; }
};
// The other way: the visitors name the public field first.
struct AssignBack {
    template <class From, class To>
    void operator()(const From& from, To& to) const { Assign{}(to, from); }
};

// Visits every pair of fields; `Pub` and `In` may be const (the direction is the visitor's).
template <class Pub, class In, class F>
void cascadeFields(Pub& p, In& i, F f) {
    f(p.count, i.count), f(p.lambda, i.lambda), f(p.blend, i.blend), f(p.distance, i.distance);
    f(p.stabilize, i.stabilize);
}

template <class Pub, class In, class F>
void shadowFields(Pub& p, In& i, F f) {
    f(p.resolution, i.resolution), f(p.depthBiasConstant, i.depthBiasConstant);
    f(p.depthBiasSlope, i.depthBiasSlope), f(p.normalOffset, i.normalOffset), f(p.filter, i.filter);
    f(p.pcfRadius, i.pcfRadius), f(p.pcssLightSize, i.pcssLightSize), f(p.pcssSunAngle, i.pcssSunAngle);
    f(p.pcssMaxRadius, i.pcssMaxRadius), f(p.blurRadius, i.blurRadius), f(p.bleedReduction, i.bleedReduction);
    f(p.evsmPositive, i.evsmPositive), f(p.evsmNegative, i.evsmNegative), f(p.msmBias, i.msmBias);
    cascadeFields(p.cascades, i.cascades, f);
    f(p.pointMode, i.pointMode), f(p.paraboloidMaxEdgeDegrees, i.paraboloidMaxEdgeDegrees), f(p.raster, i.raster);
}

// The sky's kind apart: the public kinds have no Auto (the library resolves none).
template <class Pub, class In, class F>
void skyFields(Pub& p, In& i, F f) {
    f(p.uniformRadiance, i.uniformRadiance), f(p.turbidity, i.turbidity), f(p.mapPath, i.mapPath);
    f(p.scale, i.scale), f(p.rotationDegrees, i.rotationDegrees), f(p.sunIlluminance, i.sunIlluminance);
}

template <class Pub, class In, class F>
void settingsFields(Pub& p, In& i, F f) {
    f(p.width, i.width), f(p.height, i.height), f(p.exposure, i.exposure), f(p.autoExposure, i.autoExposure);
    f(p.exposureCompensation, i.exposureCompensation);
    f(p.exposureLowPercentile, i.lighting.exposureLowPercentile);
    f(p.exposureHighPercentile, i.lighting.exposureHighPercentile);
    f(p.cameraPath, i.cameraPath);
    shadowFields(p.shadow, i.shadow, f);
    f(p.gi, i.gi), f(p.giTemporal, i.giTemporal), f(p.temporalGi, i.temporalGi);
    f(p.rsm, i.rsm), f(p.lpv, i.lpv), f(p.dsm, i.dsm), f(p.translucency, i.translucency);
    skyFields(p.sky, i.lighting.sky, f);
    f(p.skyLight, i.skyLight), f(p.overlapPasses, i.overlapPasses);
}

// The public kinds beside the internal ones (internal Auto reads as None).
constexpr std::pair<SkyKind, penumbra::SkyKind> kSkyKinds[] = {
    {SkyKind::None, penumbra::SkyKind::None},
    {SkyKind::Uniform, penumbra::SkyKind::Uniform},
    {SkyKind::Analytic, penumbra::SkyKind::Analytic},
    {SkyKind::Map, penumbra::SkyKind::Map},
};

template <class Pub, class In, class F>
void lightFields(Pub& p, In& i, F f) {
    f(p.type, i.type), f(p.position, i.position), f(p.direction, i.direction), f(p.color, i.color);
    f(p.intensity, i.intensity), f(p.range, i.range), f(p.innerConeAngle, i.innerConeAngle);
    f(p.outerConeAngle, i.outerConeAngle), f(p.castsShadow, i.castsShadow), f(p.shadowFilter, i.shadowFilter);
}

template <class Pub, class In, class F>
void cameraFields(Pub& p, In& i, F f) {
    f(p.eye, i.eye), f(p.target, i.target), f(p.up, i.up), f(p.fovy, i.fovy), f(p.znear, i.znear), f(p.zfar, i.zfar);
}

template <class A, class B>
constexpr bool same(A a, B b) { return uint32_t(a) == uint32_t(b); }
static_assert(same(ShadowFilter::Default, penumbra::ShadowFilter::Default) &&
              same(ShadowFilter::Msm, penumbra::ShadowFilter::Msm) && same(ShadowFilter::Pcf, penumbra::ShadowFilter::Pcf));
static_assert(same(PointShadowMode::Paraboloid, penumbra::PointShadowMode::Paraboloid));
static_assert(same(RasterMode::Compute, penumbra::RasterMode::Compute) && same(RasterMode::Auto, penumbra::RasterMode::Auto));
static_assert(same(GiMode::Rsm, penumbra::GiMode::Rsm) && same(GiMode::Lpv, penumbra::GiMode::Lpv));
static_assert(same(CameraPath::Gbuffer, penumbra::CameraPath::Gbuffer));
static_assert(same(LightType::Spot, penumbra::LightType::Spot) && same(LightType::Point, penumbra::LightType::Point));
static_assert(same(AlphaMode::Mask, penumbra::AlphaMode::Mask) && same(AlphaMode::Blend, penumbra::AlphaMode::Blend));

// The debug views a Settings::output names (the internal enum holds the shaders' AOV numbers).
constexpr std::pair<Output, penumbra::Aov> kOutputs[] = {
    {Output::Final, penumbra::Aov::Final},     {Output::Direct, penumbra::Aov::Direct},
    {Output::Indirect, penumbra::Aov::Indirect}, {Output::Albedo, penumbra::Aov::Albedo},
    {Output::Normal, penumbra::Aov::Normal},   {Output::Depth, penumbra::Aov::Depth},
    {Output::Shadow, penumbra::Aov::Shadow},
};

void fill(SkySettings& out, const penumbra::SkySettings& s) {
    skyFields(out, s, Assign{});
    out.kind = SkyKind::None;
    for (const auto& [pub, kind] : kSkyKinds)
        if (kind == s.kind) out.kind = pub;
}

void fill(Settings& out, const penumbra::RenderSettings& s) {
    settingsFields(out, s, Assign{});
    fill(out.sky, s.lighting.sky);
    out.output = Output::Final;
    for (const auto& [pub, aov] : kOutputs)
        if (aov == s.aov) out.output = pub;
}

void fill(Light& out, const penumbra::Light& l) { lightFields(out, l, Assign{}); }
void fill(Camera& out, const penumbra::Camera& c) { cameraFields(out, c, Assign{}); }

}  // namespace

CascadeSettings::CascadeSettings() {
    const penumbra::CascadeSettings defaults;
    cascadeFields(*this, defaults, Assign{});
}

ShadowSettings::ShadowSettings() {
    const penumbra::ShadowSettings defaults;
    shadowFields(*this, defaults, Assign{});
}

SkySettings::SkySettings() { fill(*this, penumbra::SkySettings{}); }

// An engine owns its exposure and its sky; every other default is the renderer's.
Settings::Settings() {
    fill(*this, penumbra::RenderSettings{});
    autoExposure = false;
    sky.kind = SkyKind::None;
}
Light::Light() { fill(*this, penumbra::Light{}); }
Camera::Camera() { fill(*this, penumbra::Camera{}); }

Material::Material() {
    const penumbra::Material m;
    std::memcpy(baseColor, &m.baseColor, sizeof(baseColor));
    baseColorTexture = m.baseColorTexture;
    alphaMode = AlphaMode(m.alphaMode);
    alphaCutoff = m.alphaCutoff;
    doubleSided = m.doubleSided;
}

penumbra::RenderSettings toInternal(const Settings& s) {
    penumbra::RenderSettings out;
    settingsFields(s, out, AssignBack{});
    for (const auto& [pub, kind] : kSkyKinds)
        if (pub == s.sky.kind) out.lighting.sky.kind = kind;
    for (const auto& [pub, aov] : kOutputs)
        if (pub == s.output) out.aov = aov;
    return out;
}

Settings fromInternal(const penumbra::RenderSettings& s) {
    Settings out;
    fill(out, s);
    return out;
}

penumbra::Light toInternal(const Light& l) {
    penumbra::Light out;
    lightFields(l, out, AssignBack{});
    return out;
}

Light fromInternal(const penumbra::Light& l) {
    Light out;
    fill(out, l);
    return out;
}

penumbra::Camera toInternal(const Camera& c) {
    penumbra::Camera out;
    cameraFields(c, out, AssignBack{});
    return out;
}

Camera fromInternal(const penumbra::Camera& c) {
    Camera out;
    fill(out, c);
    return out;
}

Frame fromInternal(const penumbra::Camera& camera, const std::vector<penumbra::Light>& lights,
                   const std::vector<glm::mat4>& instances) {
    Frame f;
    f.camera = fromInternal(camera);
    for (const penumbra::Light& l : lights) f.lights.push_back(fromInternal(l));
    for (const glm::mat4& m : instances) std::memcpy(f.instances.emplace_back().data(), &m, sizeof(Mat4));
    return f;
}

}  // namespace penumbra::api
