#include "reference/ray_scene.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>

namespace penumbra::reference {
namespace {

// Extends Embree's context with the kind of ray, which the filter needs to decide visibility.
struct RayContext {
    RTCIntersectContext rtc;
    bool towardsLight;  // shadow ray: casters count when their front faces the light (the far end)
};

float alphaAt(const RayScene::Triangles& tris, const Material& m, uint32_t triangle, float u, float v) {
    float alpha = m.baseColor.a;
    const Scene& scene = *tris.scene;
    if (m.baseColorTexture >= 0 && size_t(m.baseColorTexture) < tris.mips->size()) {
        const uint32_t* idx = &scene.indices[size_t(triangle) * 3];
        const glm::vec2 uv = (1.0f - u - v) * scene.vertices[idx[0]].uv + u * scene.vertices[idx[1]].uv +
                             v * scene.vertices[idx[2]].uv;
        alpha *= (*tris.mips)[m.baseColorTexture].sample(uv, glm::vec2(0.0f), glm::vec2(0.0f)).a;
    }
    return alpha;
}

// Embree filter (intersection and occlusion) of the triangles that are single-sided or cut out.
void visibilityFilter(const RTCFilterFunctionNArguments* args) {
    const auto* tris = static_cast<const RayScene::Triangles*>(args->geometryUserPtr);
    const auto* ctx = reinterpret_cast<const RayContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const uint32_t tri = tris->filteredToTriangle[RTCHitN_primID(args->hit, args->N, i)];
        const Material& m = tris->scene->materials[tris->material[tri]];
        if (!m.doubleSided) {
            const glm::vec3 d(RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                              RTCRayN_dir_z(args->ray, args->N, i));
            const float facing = glm::dot(tris->normal[tri], d);
            // A viewer at the ray origin sees the front when the ray runs against the normal; the
            // light at the far end of a shadow ray sees it when the ray runs along it.
            if (ctx->towardsLight ? facing <= 0.0f : facing >= 0.0f) {
                args->valid[i] = 0;
                continue;
            }
        }
        if (m.alphaMode != AlphaMode::Opaque &&
            alphaAt(*tris, m, tri, RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i)) <
                m.alphaCutoff)
            args->valid[i] = 0;
    }
}

void initRay(RTCRay& r, const glm::vec3& o, const glm::vec3& d, float tmin, float tmax) {
    r.org_x = o.x, r.org_y = o.y, r.org_z = o.z;
    r.dir_x = d.x, r.dir_y = d.y, r.dir_z = d.z;
    r.tnear = tmin;
    r.tfar = tmax;
    r.time = 0.0f;
    r.mask = ~0u;
    r.id = 0;
    r.flags = 0;
}

}  // namespace

RayScene::RayScene(const Scene& scene) : scene_(scene) {
    device_ = rtcNewDevice(nullptr);
    if (!device_) throw std::runtime_error("cannot create an Embree device (error " +
                                           std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
    rtcScene_ = rtcNewScene(device_);
    rtcSetSceneFlags(rtcScene_, RTC_SCENE_FLAG_ROBUST);  // watertight: no light leaks at the box's edges
    rtcSetSceneBuildQuality(rtcScene_, RTC_BUILD_QUALITY_HIGH);

    tris_.scene = &scene;
    tris_.mips = &mips_;
    // The mip levels the renderer shades with (texture.h says why); building the chains is the slow
    // part of loading a textured scene, so the textures are shared out between threads.
    std::vector<std::optional<MipChain>> chains(scene.textures.size());
    std::atomic<size_t> next{0};
    std::vector<std::thread> pool;
    for (uint32_t i = 0; i < std::min<size_t>(std::max(1u, std::thread::hardware_concurrency()), chains.size()); ++i)
        pool.emplace_back([&] {
            for (size_t k; (k = next.fetch_add(1)) < chains.size();) chains[k].emplace(scene.textures[k]);
        });
    for (std::thread& t : pool) t.join();
    for (std::optional<MipChain>& c : chains) mips_.push_back(std::move(*c));
    const size_t count = scene.triangleCount();
    tris_.material.assign(count, 0);
    tris_.normal.resize(count);
    for (const Draw& d : scene.draws)
        for (uint32_t k = d.firstIndex / 3; k < (d.firstIndex + d.indexCount) / 3 && k < count; ++k)
            tris_.material[k] = std::min<uint32_t>(d.material, uint32_t(scene.materials.size() - 1));
    std::vector<uint32_t> opaque, filtered;
    for (size_t k = 0; k < count; ++k) {
        const uint32_t* idx = &scene.indices[k * 3];
        const glm::vec3 a = scene.vertices[idx[0]].position, b = scene.vertices[idx[1]].position,
                        c = scene.vertices[idx[2]].position;
        tris_.normal[k] = glm::cross(b - a, c - a);  // glTF fronts are counter-clockwise
        const Material& m = scene.materials[tris_.material[k]];
        (m.doubleSided && m.alphaMode == AlphaMode::Opaque ? opaque : filtered).push_back(uint32_t(k));
    }
    // Filter callbacks cost a call per candidate hit: only the triangles that need one get one.
    opaqueToTriangle_ = opaque;
    tris_.filteredToTriangle = filtered;
    if (!opaque.empty()) addGeometry(opaque, false);
    if (!filtered.empty()) addGeometry(filtered, true);
    rtcCommitScene(rtcScene_);
    if (rtcGetDeviceError(device_) != RTC_ERROR_NONE)
        throw std::runtime_error("Embree could not build the scene's BVH");
}

void RayScene::addGeometry(const std::vector<uint32_t>& triangles, bool filtered) {
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Embree owns copies: 16-byte vertices (it may read a fourth float) and 3 indices per triangle.
    auto* verts = static_cast<float*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 16, triangles.size() * 3));
    auto* idx = static_cast<uint32_t*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 12, triangles.size()));
    for (size_t k = 0; k < triangles.size(); ++k)
        for (int j = 0; j < 3; ++j) {
            const glm::vec3& p = scene_.vertices[scene_.indices[size_t(triangles[k]) * 3 + j]].position;
            float* v = verts + (k * 3 + j) * 4;
            v[0] = p.x, v[1] = p.y, v[2] = p.z, v[3] = 0.0f;
            idx[k * 3 + j] = uint32_t(k * 3 + j);
        }
    if (filtered) {
        rtcSetGeometryUserData(g, &tris_);
        rtcSetGeometryIntersectFilterFunction(g, visibilityFilter);
        rtcSetGeometryOccludedFilterFunction(g, visibilityFilter);
    }
    rtcCommitGeometry(g);
    (filtered ? filteredGeometry_ : opaqueGeometry_) = rtcAttachGeometry(rtcScene_, g);
    rtcReleaseGeometry(g);
}

RayScene::~RayScene() {
    if (rtcScene_) rtcReleaseScene(rtcScene_);
    if (device_) rtcReleaseDevice(device_);
}

float RayScene::epsilon(const glm::vec3& p) {
    const float m = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 1.0f});
    return 2e-4f * m;  // a few thousand float ulps: clears the surface, far below any modelled detail
}

std::optional<Hit> RayScene::intersect(const glm::vec3& origin, const glm::vec3& dir, float tmin, float tmax) const {
    RayContext ctx;
    rtcInitIntersectContext(&ctx.rtc);
    ctx.towardsLight = false;
    RTCRayHit rh;
    initRay(rh.ray, origin, dir, tmin, tmax);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(rtcScene_, &ctx.rtc, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    return Hit{rh.ray.tfar, triangleOf(rh.hit.geomID, rh.hit.primID), rh.hit.u, rh.hit.v};
}

bool RayScene::occluded(const glm::vec3& origin, const glm::vec3& dir, float tmax) const {
    RayContext ctx;
    rtcInitIntersectContext(&ctx.rtc);
    ctx.towardsLight = true;
    RTCRay r;
    initRay(r, origin, dir, 0.0f, tmax);
    rtcOccluded1(rtcScene_, &ctx.rtc, &r);
    return r.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}

// uv where the ray (o, d) meets the plane of `triangle` (barycentrics extended outside it), or
// nullopt when the ray runs along the plane.
std::optional<glm::vec2> RayScene::planeUv(uint32_t triangle, const glm::vec3& o, const glm::vec3& d) const {
    const uint32_t* idx = &scene_.indices[size_t(triangle) * 3];
    const Vertex &a = scene_.vertices[idx[0]], &b = scene_.vertices[idx[1]], &c = scene_.vertices[idx[2]];
    const glm::vec3 n = tris_.normal[triangle];
    const float nd = glm::dot(n, d), nn = glm::dot(n, n);
    if (std::abs(nd) < 1e-12f * std::sqrt(nn) || nn <= 0.0f) return std::nullopt;
    const glm::vec3 p = o + d * (glm::dot(n, a.position - o) / nd);
    const float u = glm::dot(n, glm::cross(p - a.position, c.position - a.position)) / nn;
    const float v = glm::dot(n, glm::cross(b.position - a.position, p - a.position)) / nn;
    return (1.0f - u - v) * a.uv + u * b.uv + v * c.uv;
}

SurfacePoint RayScene::surface(const Hit& hit, const glm::vec3& dir, const PixelFootprint* footprint) const {
    const uint32_t* idx = &scene_.indices[size_t(hit.triangle) * 3];
    const Vertex &a = scene_.vertices[idx[0]], &b = scene_.vertices[idx[1]], &c = scene_.vertices[idx[2]];
    const float w = 1.0f - hit.u - hit.v;
    SurfacePoint s;
    s.position = w * a.position + hit.u * b.position + hit.v * c.position;
    glm::vec3 ng = glm::normalize(tris_.normal[hit.triangle]);
    s.geometricNormal = glm::dot(ng, dir) > 0.0f ? -ng : ng;
    glm::vec3 ns = w * a.normal + hit.u * b.normal + hit.v * c.normal;
    ns = glm::dot(ns, ns) > 1e-20f ? glm::normalize(ns) : s.geometricNormal;
    // Two-sided shading as in the renderer's lighting pass: the side the viewer sees.
    s.shadingNormal = glm::dot(ns, dir) > 0.0f ? -ns : ns;
    const Material& m = scene_.materials[tris_.material[hit.triangle]];
    glm::vec4 base = m.baseColor;
    if (m.baseColorTexture >= 0 && size_t(m.baseColorTexture) < mips_.size()) {
        const glm::vec2 uv = w * a.uv + hit.u * b.uv + hit.v * c.uv;
        std::optional<glm::vec2> ux, uy;
        if (footprint) {
            ux = planeUv(hit.triangle, footprint->origin, footprint->dirX);
            uy = planeUv(hit.triangle, footprint->origin, footprint->dirY);
        }
        base *= ux && uy ? mips_[m.baseColorTexture].sample(uv, *ux - uv, *uy - uv)
                         : mips_[m.baseColorTexture].sample(uv, glm::vec2(0.0f), glm::vec2(0.0f));
    }
    s.albedo = glm::vec3(base);
    return s;
}

}  // namespace penumbra::reference
