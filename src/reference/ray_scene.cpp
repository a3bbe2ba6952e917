#include "reference/ray_scene.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>

#include "reference/sampling.h"

namespace penumbra::reference {
namespace {

// Extends Embree's context with the kind of ray, which the filters need to decide visibility, and
// the translucent surfaces the ray has met.
struct RayContext {
    RTCIntersectContext rtc;
    bool towardsLight;  // shadow ray: casters count when their front faces the light (the far end)
    RayQuery query;
    float transmittance = 1.0f;  // shadow ray: prod (1 - alpha) of the translucent surfaces so far
    // Embree may report one crossing of a surface more than once: a primitive referenced twice
    // (spatial splits), both triangles at their shared edge, both segments at a strand's joint. A
    // crossing is one (geometry, object: material or strand) at one distance, within `tolerance`,
    // and keeps its first decision. Beyond the capacity crossings are decided unrecorded (a shadow
    // ray is far below kOpaqueTransmittance by then unless alphas are tiny).
    struct Crossing {
        uint32_t geometry, object;
        float t, tolerance;
        bool stops;
    };
    static constexpr uint32_t kCapacity = 96;
    uint32_t count = 0;
    Crossing crossings[kCapacity];
};

// Whether a translucent surface of opacity `alpha` at distance t stops the ray (the filter keeps the
// hit) or lets it pass (the filter rejects it and the traversal goes on).
bool stopsRay(RayContext& ctx, float alpha, uint32_t geometry, uint32_t object, uint32_t primitive, float t,
              float tolerance) {
    if (ctx.query.opaqueOnly) return false;
    for (uint32_t i = 0; i < ctx.count; ++i) {
        const RayContext::Crossing& c = ctx.crossings[i];
        if (c.geometry == geometry && c.object == object && std::abs(c.t - t) <= std::max(c.tolerance, tolerance))
            return c.stops;
    }
    alpha = std::clamp(alpha, 0.0f, 1.0f);
    bool stops;
    if (ctx.towardsLight) {
        ctx.transmittance *= 1.0f - alpha;
        stops = ctx.transmittance < RayScene::kOpaqueTransmittance;  // as good as opaque: end the traversal
    } else {  // a viewer's ray: opaque with probability alpha
        stops = float(mix64(mix64(ctx.query.seed) ^ (uint64_t(geometry) << 32 | primitive)) >> 40) * 0x1p-24f < alpha;
    }
    if (ctx.count < RayContext::kCapacity) ctx.crossings[ctx.count++] = {geometry, object, t, tolerance, stops};
    return stops;
}

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

// Embree filter (intersection and occlusion) of the triangles that are single-sided, cut out or blended.
void visibilityFilter(const RTCFilterFunctionNArguments* args) {
    const auto* tris = static_cast<const RayScene::Triangles*>(args->geometryUserPtr);
    auto* ctx = reinterpret_cast<RayContext*>(args->context);
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
        if (m.alphaMode == AlphaMode::Opaque) continue;
        const float alpha = alphaAt(*tris, m, tri, RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i));
        if (m.alphaMode == AlphaMode::Mask) {
            if (alpha < m.alphaCutoff) args->valid[i] = 0;
            continue;
        }
        const float t = RTCRayN_tfar(args->ray, args->N, i);  // a candidate's distance
        if (!stopsRay(*ctx, alpha, RTCHitN_geomID(args->hit, args->N, i), tris->material[tri],
                      RTCHitN_primID(args->hit, args->N, i), t, 1e-5f * (1.0f + t)))
            args->valid[i] = 0;
    }
}

// Embree filter of the hair strands: each is translucent with its opacity; a ray ignores the strand
// it leaves.
void strandFilter(const RTCFilterFunctionNArguments* args) {
    const auto* strands = static_cast<const RayScene::Strands*>(args->geometryUserPtr);
    auto* ctx = reinterpret_cast<RayContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
        const uint32_t strand = strands->strand[prim];
        const Strand& s = strands->scene->strands[strand];
        if (int32_t(strand) == ctx->query.skipStrand ||
            !stopsRay(*ctx, s.opacity, RTCHitN_geomID(args->hit, args->N, i), strand, prim,
                      RTCRayN_tfar(args->ray, args->N, i), 2.0f * s.width))
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
        translucent_ |= m.alphaMode == AlphaMode::Blend;
        singleSided_ |= !m.doubleSided;
    }
    // Filter callbacks cost a call per candidate hit: only the triangles that need one get one.
    opaqueToTriangle_ = opaque;
    tris_.filteredToTriangle = filtered;
    if (!opaque.empty()) addGeometry(opaque, false);
    if (!filtered.empty()) addGeometry(filtered, true);
    if (!scene.strands.empty()) addStrands();
    translucent_ |= !scene.strands.empty();
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

// Every strand segment as a flat linear curve (a ribbon facing the ray) of the strand's width.
void RayScene::addStrands() {
    strands_.scene = &scene_;
    for (uint32_t k = 0; k < scene_.strands.size(); ++k)
        for (uint32_t j = 0; j + 1 < scene_.strands[k].pointCount; ++j) {
            strands_.firstPoint.push_back(scene_.strands[k].firstPoint + j);
            strands_.strand.push_back(k);
        }
    if (strands_.strand.empty()) return;
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_FLAT_LINEAR_CURVE);
    auto* verts = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 16,
                                                              scene_.strandPoints.size()));
    std::fill(verts, verts + scene_.strandPoints.size() * 4, 0.0f);
    for (const Strand& s : scene_.strands)
        for (uint32_t j = 0; j < s.pointCount; ++j) {
            const glm::vec3& p = scene_.strandPoints[s.firstPoint + j];
            float* v = verts + size_t(s.firstPoint + j) * 4;
            v[0] = p.x, v[1] = p.y, v[2] = p.z, v[3] = 0.5f * std::max(s.width, 0.0f);  // radius
            curveBack_ = std::max(curveBack_, 2.02f * v[3]);
        }
    auto* idx = static_cast<uint32_t*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, 4, strands_.firstPoint.size()));
    std::copy(strands_.firstPoint.begin(), strands_.firstPoint.end(), idx);
    rtcSetGeometryUserData(g, &strands_);
    rtcSetGeometryIntersectFilterFunction(g, strandFilter);
    rtcSetGeometryOccludedFilterFunction(g, strandFilter);
    rtcCommitGeometry(g);
    strandGeometry_ = rtcAttachGeometry(rtcScene_, g);
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

std::optional<Hit> RayScene::intersect(const glm::vec3& origin, const glm::vec3& dir, float tmin, float tmax,
                                       const RayQuery& query) const {
    RayContext ctx;
    rtcInitIntersectContext(&ctx.rtc);
    ctx.towardsLight = false;
    ctx.query = query;
    RTCRayHit rh;
    initRay(rh.ray, origin - curveBack_ * dir, dir, tmin + curveBack_, tmax + curveBack_);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(rtcScene_, &ctx.rtc, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    if (rh.hit.geomID == strandGeometry_)
        return Hit{rh.ray.tfar - curveBack_, strands_.firstPoint[rh.hit.primID], rh.hit.u, rh.hit.v,
                   int32_t(strands_.strand[rh.hit.primID])};
    return Hit{rh.ray.tfar - curveBack_, triangleOf(rh.hit.geomID, rh.hit.primID), rh.hit.u, rh.hit.v};
}

float RayScene::transmittance(const glm::vec3& origin, const glm::vec3& dir, float tmax, int32_t skipStrand) const {
    RayContext ctx;
    rtcInitIntersectContext(&ctx.rtc);
    ctx.towardsLight = true;
    ctx.query.skipStrand = skipStrand;
    RTCRay r;
    initRay(r, origin - curveBack_ * dir, dir, curveBack_, tmax + curveBack_);
    rtcOccluded1(rtcScene_, &ctx.rtc, &r);
    return r.tfar < 0.0f ? 0.0f : ctx.transmittance;  // Embree sets tfar to -inf on a kept hit
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

// A strand hit: the point on the segment's axis (the ribbon is at most half a width from it), lit
// along the segment's direction; its normals point back along the ray, to the viewer (Kajiya-Kay's
// view direction; a strand's rays leave from its axis, so no offset reads them).
SurfacePoint RayScene::strandSurface(const Hit& hit, const glm::vec3& dir) const {
    const glm::vec3 a = scene_.strandPoints[hit.triangle], b = scene_.strandPoints[hit.triangle + 1];
    SurfacePoint s;
    s.position = a + hit.u * (b - a);
    s.geometricNormal = s.shadingNormal = -dir;
    s.albedo = scene_.strands[hit.strand].color;
    s.strand = hit.strand;
    s.tangent = glm::length(b - a) > 0.0f ? glm::normalize(b - a) : glm::vec3(0.0f, 1.0f, 0.0f);
    return s;
}

SurfacePoint RayScene::surface(const Hit& hit, const glm::vec3& dir, const PixelFootprint* footprint) const {
    if (hit.strand >= 0) return strandSurface(hit, dir);
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
