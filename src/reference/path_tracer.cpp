#include "reference/path_tracer.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>

#include "scene/animation.h"

#include "reference/ray_scene.h"
#include "reference/sampling.h"

namespace penumbra {
namespace {

using reference::Hit;
using reference::RayScene;
using reference::SurfacePoint;

constexpr float kPi = 3.14159265358979f;
constexpr uint32_t kTile = 16;

// A pinhole camera with the rasterizer's convention (glm::lookAt, vertical fovy, top row first).
struct PinholeCamera {
    glm::vec3 eye, forward, right, up;
    float tanHalf, aspect, znear, zfar;

    PinholeCamera(const Camera& c, uint32_t w, uint32_t h)
        : eye(c.eye), forward(glm::normalize(c.target - c.eye)), tanHalf(std::tan(0.5f * c.fovy)),
          aspect(float(w) / float(h)), znear(c.znear), zfar(c.zfar > 0.0f ? c.zfar : 0.0f) {
        right = glm::normalize(glm::cross(forward, c.up));
        up = glm::cross(right, forward);
    }
    // Direction through image point (sx, sy) in pixels (x right, y down; pixel centres at +0.5).
    glm::vec3 direction(float sx, float sy, uint32_t w, uint32_t h) const {
        const float x = (sx / float(w) * 2.0f - 1.0f) * tanHalf * aspect;
        const float y = (1.0f - sy / float(h) * 2.0f) * tanHalf;
        return glm::normalize(forward + x * right + y * up);
    }
};

// Kajiya-Kay hair shading as shaders/dsm/kajiya_kay.glsl defines it (written again from the formula,
// docs/techniques/dsm.md), per unit irradiance facing the light: a strand of unit tangent t lit
// from l, seen from v. Diffuse albedo / pi sin(t, l); a white specular cone lobe around t,
// (n + 2) / (2 pi) cos^n with cos = sin(t,l) sin(t,v) - (t.l)(t.v), times sin(t, l).
constexpr float kHairSpecular = 0.08f, kHairExponent = 60.0f;  // the renderer's constants

glm::vec3 kajiyaKay(const glm::vec3& albedo, const glm::vec3& t, const glm::vec3& l, const glm::vec3& v) {
    const float tl = glm::dot(t, l), tv = glm::dot(t, v);
    const float sinTL = std::sqrt(std::max(0.0f, 1.0f - tl * tl)), sinTV = std::sqrt(std::max(0.0f, 1.0f - tv * tv));
    const float cone = std::max(0.0f, sinTL * sinTV - tl * tv);
    const float specular = kHairSpecular * (kHairExponent + 2.0f) / (2.0f * kPi) * std::pow(cone, kHairExponent);
    return (albedo / kPi + glm::vec3(specular)) * sinTL;
}

struct Tracer {
    const Scene& scene;
    const RayScene& rays;
    uint32_t bounces;
    const Sky& sky;

    // Fraction of the light along unit `toLight` (at `dist`) that reaches s: a strand's shadow ray
    // leaves from its axis and ignores its own strand; a surface's from just above it.
    float visibility(const SurfacePoint& s, const glm::vec3& toLight, float dist, uint64_t& count) const {
        const float eps = RayScene::epsilon(s.position);
        const float tmax = std::isinf(dist) ? std::numeric_limits<float>::infinity() : dist - 2.0f * eps;
        if (tmax <= 0.0f) return 1.0f;
        ++count;
        return s.strand >= 0 ? rays.transmittance(s.position, toLight, tmax, s.strand)
                             : rays.transmittance(s.position + eps * s.geometricNormal, toLight, tmax);
    }

    // Radiance s reflects towards its viewer from every light (next-event estimation; a punctual
    // light is a delta: one shadow ray each, no noise): Lambert for surfaces, Kajiya-Kay for strands
    // (whose shadingNormal points to the viewer).
    glm::vec3 direct(const SurfacePoint& s, uint64_t& count) const {
        glm::vec3 sum(0.0f), hair(0.0f);
        for (const Light& l : scene.lights) {
            glm::vec3 toLight;
            float dist;
            const glm::vec3 e = referenceIrradiance(l, s.position, toLight, dist);
            const float cosine = s.strand >= 0 ? 1.0f : glm::dot(s.shadingNormal, toLight);
            if (cosine <= 0.0f || e == glm::vec3(0.0f)) continue;
            // Unshadowed lights are unshadowed in the renderer too.
            const float v = l.castsShadow ? visibility(s, toLight, dist, count) : 1.0f;
            if (v <= 0.0f) continue;
            if (s.strand >= 0) hair += e * v * kajiyaKay(s.albedo, s.tangent, toLight, s.shadingNormal);
            else sum += e * (cosine * v);
        }
        return sum * s.albedo / kPi + hair;
    }

    // The renderer's shadow AOV: visibility of the first light that casts shadows at s (0 where it
    // does not light s).
    float firstShadow(const SurfacePoint& s, uint64_t& count) const {
        for (const Light& l : scene.lights) {
            if (!l.castsShadow) continue;
            glm::vec3 toLight;
            float dist;
            const glm::vec3 e = referenceIrradiance(l, s.position, toLight, dist);
            if ((s.strand < 0 && glm::dot(s.shadingNormal, toLight) <= 0.0f) || e == glm::vec3(0.0f)) return 0.0f;
            return visibility(s, toLight, dist, count);
        }
        return 1.0f;
    }

    // The next direction of a path leaving s and the path weight's factor. A surface: cosine-weighted
    // (pdf cos/pi: the albedo). A strand: Kajiya-Kay's diffuse lobe, (albedo / pi) sin(t, l) over the
    // whole sphere, sampled uniformly (pdf 1 / 4 pi); its specular lobe is left out of bounces.
    glm::vec3 scatter(const SurfacePoint& s, reference::Pcg32& rng, glm::vec3& dir) const {
        const float u1 = rng.uniform(), u2 = rng.uniform();
        if (s.strand < 0) {
            dir = reference::cosineSample(s.shadingNormal, u1, u2);
            return s.albedo;
        }
        const float z = 1.0f - 2.0f * u1, r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 2.0f * kPi * u2;
        dir = glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
        const float tl = glm::dot(s.tangent, dir);
        return 4.0f * s.albedo * std::sqrt(std::max(0.0f, 1.0f - tl * tl));
    }

    // The sky's light at s by sampling the sky, weighted against the scatter's density for the same
    // direction (power heuristic). A strand's specular lobe is not sampled by scatter(): at strands
    // the sky is sampled alone (weight 1) and escaping scatter rays add nothing.
    glm::vec3 skyLight(const SurfacePoint& s, reference::Pcg32& rng, uint64_t& count) const {
        if (!sky.enabled()) return glm::vec3(0.0f);
        const SkySample l = sky.sample({rng.uniform(), rng.uniform()});
        if (l.pdf <= 0.0f) return glm::vec3(0.0f);
        glm::vec3 f;
        float weight = 1.0f;
        if (s.strand >= 0) {
            f = kajiyaKay(s.albedo, s.tangent, l.direction, s.shadingNormal);
        } else {
            const float cosine = glm::dot(s.shadingNormal, l.direction);
            if (cosine <= 0.0f) return glm::vec3(0.0f);
            f = s.albedo * (cosine / kPi);
            weight = powerHeuristic(l.pdf, cosine / kPi);
        }
        const float v = visibility(s, l.direction, std::numeric_limits<float>::infinity(), count);
        return v > 0.0f ? f * l.radiance * (v * weight / l.pdf) : glm::vec3(0.0f);
    }

    static float powerHeuristic(float a, float b) { return a * a / std::max(a * a + b * b, 1e-30f); }

    struct PathLight {
        glm::vec3 direct{0.0f};    // the sky at the first vertex, unoccluded
        glm::vec3 indirect{0.0f};  // everything reflected on the way
    };

    // The sky along a surface's scatter direction with path weight `next`, weighted against
    // skyLight()'s sample of it; `seen` is the share of it that reaches the surface.
    glm::vec3 skyScattered(const SurfacePoint& s, const glm::vec3& next, const glm::vec3& dir, float seen) const {
        const float scatterPdf = std::max(0.0f, glm::dot(s.shadingNormal, dir)) / kPi;
        return next * sky.radiance(dir) * (seen * powerHeuristic(scatterPdf, sky.pdf(dir)));
    }

    // The light of a path from the camera's surface s: every vertex is lit by next-event estimation
    // (the sky by MIS), `bounces` scatters add further vertices; with a sky the last vertex's scatter
    // ray is traced too, for the sky it sees. In a scene with translucent surfaces each bounce ray
    // draws its own seed for them.
    // The sky's light follows the light's rule for single-sided triangles in both halves of the MIS
    // (skyLight()'s shadow ray, and here the scatter direction's own transmittance), while the path
    // goes on by the viewer's: a dome whose fronts face inward lets the sky in and is seen from
    // inside. Without single-sided triangles the two rules agree, and the escaping ray is the test.
    PathLight path(SurfacePoint s, reference::Pcg32& rng, uint64_t& count) const {
        PathLight out;
        glm::vec3 throughput(1.0f);
        for (uint32_t b = 0;; ++b) {
            glm::vec3& term = b == 0 ? out.direct : out.indirect;
            term += throughput * skyLight(s, rng, count);
            if (b >= bounces && !sky.enabled()) break;
            glm::vec3 dir;
            const glm::vec3 next = throughput * scatter(s, rng, dir);
            if (next == glm::vec3(0.0f)) break;
            const float eps = RayScene::epsilon(s.position);
            const glm::vec3 origin =
                s.strand >= 0 ? s.position
                              : s.position + eps * (glm::dot(dir, s.geometricNormal) >= 0.0f ? s.geometricNormal
                                                                                              : -s.geometricNormal);
            const bool skyByLight = sky.enabled() && s.strand < 0 && rays.singleSided();
            if (skyByLight) {
                ++count;
                const float seen = rays.transmittance(origin, dir, std::numeric_limits<float>::infinity());
                if (seen > 0.0f) term += skyScattered(s, next, dir, seen);
                if (b >= bounces) break;
            }
            const reference::RayQuery query{rays.translucent() ? rng.next() : 0u, s.strand, false};
            ++count;
            const std::optional<Hit> hit =
                rays.intersect(origin, dir, 0.0f, std::numeric_limits<float>::infinity(), query);
            if (!hit) {
                if (sky.enabled() && s.strand < 0 && !skyByLight) term += skyScattered(s, next, dir, 1.0f);
                break;
            }
            if (b >= bounces) break;
            s = rays.surface(*hit, dir);
            throughput = next;
            out.indirect += throughput * direct(s, count);
        }
        return out;
    }
};

struct Accumulator {
    glm::dvec3 sum{0.0}, sumSq{0.0};
    void add(const glm::vec3& v) {
        sum += glm::dvec3(v);
        sumSq += glm::dvec3(v) * glm::dvec3(v);
    }
    // Mean and variance of the mean of n samples (unbiased sample variance / n).
    void finish(uint32_t n, glm::vec3& mean, glm::vec3& varianceOfMean) const {
        const glm::dvec3 m = sum / double(n);
        mean = glm::vec3(m);
        if (n < 2) {
            varianceOfMean = glm::vec3(0.0f);
            return;
        }
        const glm::dvec3 variance = glm::max(sumSq / double(n) - m * m, 0.0) * (double(n) / double(n - 1));
        varianceOfMean = glm::vec3(variance / double(n));
    }
};

void renderPixel(const Tracer& tracer, const PinholeCamera& cam, const ReferenceSettings& s, uint32_t x, uint32_t y,
                 ReferenceImage& out, uint64_t& count) {
    const size_t index = size_t(y) * s.width + x;
    reference::Pcg32 rng(s.seed, index);
    Accumulator direct, indirect;
    double shadow = 0.0;
    uint32_t strandHits = 0;
    // Without anti-aliasing every path shares the centre ray and its direct light: trace them once,
    // unless translucent surfaces make the camera ray itself random.
    const bool translucent = tracer.rays.translucent();
    const uint32_t primaries = s.antialias || translucent ? s.spp : 1;
    for (uint32_t p = 0; p < primaries; ++p) {
        const float jx = s.antialias ? rng.uniform() : 0.5f, jy = s.antialias ? rng.uniform() : 0.5f;
        const glm::vec3 dir = cam.direction(float(x) + jx, float(y) + jy, s.width, s.height);
        // The rasterizer clips at planes perpendicular to the view axis, not at spheres.
        const float along = glm::dot(dir, cam.forward);
        const float tmin = cam.znear / along;
        const float tmax = cam.zfar > 0.0f ? cam.zfar / along : std::numeric_limits<float>::infinity();
        ++count;
        const reference::RayQuery query{translucent ? rng.next() : 0u, -1, false};
        const std::optional<Hit> hit = tracer.rays.intersect(cam.eye, dir, tmin, tmax, query);
        // The shadow AOV is the opaque surface's, behind any translucent layers (as the renderer's).
        const std::optional<Hit> opaque =
            translucent ? tracer.rays.intersect(cam.eye, dir, tmin, tmax, {0u, -1, true}) : hit;
        if (opaque) shadow += tracer.firstShadow(tracer.rays.surface(*opaque, dir), count);
        const uint32_t paths = primaries == s.spp ? 1 : s.spp;
        if (!hit) {  // the sky the camera sees
            const glm::vec3 skySeen = tracer.sky.radiance(dir);
            for (uint32_t k = 0; k < paths; ++k) direct.add(skySeen), indirect.add(glm::vec3(0.0f));
            continue;
        }
        out.covered[index] = 1;
        strandHits += hit->strand >= 0;
        // The texture footprint of the pixel, as the rasterizer's derivatives see it.
        const float px = float(x) + jx, py = float(y) + jy;
        const reference::PixelFootprint footprint{cam.eye, cam.direction(px + 1.0f, py, s.width, s.height),
                                                  cam.direction(px, py + 1.0f, s.width, s.height)};
        const SurfacePoint sp = tracer.rays.surface(*hit, dir, &footprint);
        const glm::vec3 d = tracer.direct(sp, count);
        for (uint32_t k = 0; k < paths; ++k) {
            const Tracer::PathLight light = tracer.path(sp, rng, count);
            direct.add(d + light.direct);
            indirect.add(light.indirect);
        }
    }
    direct.finish(s.spp, out.direct[index], out.directVar[index]);
    indirect.finish(s.spp, out.indirect[index], out.indirectVar[index]);
    out.shadow[index] = float(shadow / primaries);
    out.hair[index] = float(strandHits) / float(primaries);
}

// "reference: [#######.............]  35%  12.4 s" on one line of stderr, redrawn with \r.
void drawProgress(double fraction, double seconds) {
    constexpr int kWidth = 30;
    const int filled = int(fraction * kWidth);
    fmt::print(stderr, "\rreference: [{}{}] {:3.0f}%  {:.1f} s", std::string(filled, '#'),
               std::string(kWidth - filled, '.'), 100.0 * fraction, seconds);
    std::fflush(stderr);
}

}  // namespace

ReferenceAov parseReferenceAov(const std::string& name) {
    if (name == "final") return ReferenceAov::Final;
    if (name == "direct") return ReferenceAov::Direct;
    if (name == "indirect") return ReferenceAov::Indirect;
    if (name == "mask") return ReferenceAov::Mask;
    if (name == "shadow") return ReferenceAov::Shadow;
    if (name == "hair") return ReferenceAov::Hair;
    throw std::invalid_argument("AOV '" + name + "': the reference writes final, direct, indirect, mask, shadow or hair");
}

std::vector<float> ReferenceImage::rgba(ReferenceAov aov) const {
    std::vector<float> out(size_t(width) * height * 4);
    for (size_t i = 0; i < size_t(width) * height; ++i) {
        glm::vec3 v = aov == ReferenceAov::Direct     ? direct[i]
                      : aov == ReferenceAov::Indirect ? indirect[i]
                      : aov == ReferenceAov::Mask     ? glm::vec3(float(covered[i]))
                      : aov == ReferenceAov::Shadow   ? glm::vec3(shadow[i])
                      : aov == ReferenceAov::Hair     ? glm::vec3(hair[i])
                                                      : direct[i] + indirect[i];
        out[i * 4] = v.x, out[i * 4 + 1] = v.y, out[i * 4 + 2] = v.z, out[i * 4 + 3] = 1.0f;
    }
    return out;
}

double ReferenceImage::relativeNoise(ReferenceAov aov, const std::vector<uint8_t>& mask) const {
    double var = 0.0, sq = 0.0;
    for (size_t i = 0; i < covered.size(); ++i) {
        if (!(mask.empty() ? covered[i] : mask[i])) continue;
        const double d = aov != ReferenceAov::Indirect ? 1.0 : 0.0, in = aov != ReferenceAov::Direct ? 1.0 : 0.0;
        const glm::dvec3 v = d * glm::dvec3(directVar[i]) + in * glm::dvec3(indirectVar[i]);
        const glm::dvec3 m = d * glm::dvec3(direct[i]) + in * glm::dvec3(indirect[i]);
        var += v.x + v.y + v.z, sq += glm::dot(m, m);
    }
    return sq > 0.0 ? std::sqrt(var / sq) : 0.0;
}

glm::vec3 referenceIrradiance(const Light& light, const glm::vec3& p, glm::vec3& toLight, float& distance) {
    const glm::vec3 radiantColour = light.color * light.intensity;
    if (light.type == LightType::Directional) {
        toLight = -glm::normalize(light.direction);
        distance = std::numeric_limits<float>::infinity();
        return radiantColour;  // E on a surface facing the light
    }
    const glm::vec3 v = light.position - p;
    const float d2 = std::max(glm::dot(v, v), 1e-8f);
    distance = std::sqrt(d2);
    toLight = v / distance;
    float falloff = 1.0f / d2;  // radiant intensity I -> irradiance I / d^2
    if (light.range > 0.0f) {   // KHR_lights_punctual's recommended window, (1 - (d/r)^4)^2 clamped
        const float q = distance / light.range;
        const float w = std::clamp(1.0f - q * q * q * q, 0.0f, 1.0f);
        falloff *= w * w;
    }
    if (light.type == LightType::Spot) {  // t^2 across the cone edge, t linear in the cosine
        const float cosOuter = std::cos(light.outerConeAngle), cosInner = std::cos(light.innerConeAngle);
        const float c = glm::dot(-toLight, glm::normalize(light.direction));
        const float t = std::clamp((c - cosOuter) / std::max(cosInner - cosOuter, 1e-4f), 0.0f, 1.0f);
        falloff *= t * t;
    }
    return radiantColour * falloff;
}

ReferenceImage renderReference(const Scene& scene, const Camera& camera, const ReferenceSettings& s) {
    if (s.width == 0 || s.height == 0 || s.width > 16384 || s.height > 16384)
        throw std::invalid_argument(fmt::format("reference image size {}x{}: expected 1..16384", s.width, s.height));
    if (s.spp == 0) throw std::invalid_argument("0 paths per pixel: at least one is needed");
    if (s.bounces > kMaxReferenceBounces)
        throw std::invalid_argument(fmt::format("{} bounces: expected 0..{}", s.bounces, kMaxReferenceBounces));
    if (scene.indices.empty()) throw std::invalid_argument("the scene has no triangles to trace");
    // Instanced meshes are traced as world-space copies (at rest; a caller with a time passes the
    // scene's worldSpaceScene at that time).
    if (scene.instances.size() > 1)
        return renderReference(worldSpaceScene(scene, instanceTransforms(scene, nodeWorldTransforms(scene, 0.0, {}))),
                               camera, s);

    const auto start = std::chrono::steady_clock::now();
    const RayScene rays(scene);
    ReferenceImage out;
    const Sky sky = makeSky(s.sky, scene.lights, out.warnings);
    const Tracer tracer{scene, rays, s.bounces, sky};
    const PinholeCamera cam(camera, s.width, s.height);
    out.width = s.width, out.height = s.height, out.spp = s.spp;
    const size_t n = size_t(s.width) * s.height;
    out.direct.resize(n), out.indirect.resize(n), out.directVar.resize(n), out.indirectVar.resize(n);
    out.covered.assign(n, 0);
    out.shadow.assign(n, 0.0f);
    out.hair.assign(n, 0.0f);

    const uint32_t tilesX = (s.width + kTile - 1) / kTile, tilesY = (s.height + kTile - 1) / kTile;
    const uint32_t tiles = tilesX * tilesY;
    std::atomic<uint32_t> nextTile{0}, doneTiles{0};
    std::atomic<uint64_t> rayTotal{0};
    auto worker = [&] {
        uint64_t count = 0;
        for (uint32_t t; (t = nextTile.fetch_add(1)) < tiles; doneTiles.fetch_add(1)) {
            const uint32_t x0 = (t % tilesX) * kTile, y0 = (t / tilesX) * kTile;
            for (uint32_t y = y0; y < std::min(y0 + kTile, s.height); ++y)
                for (uint32_t x = x0; x < std::min(x0 + kTile, s.width); ++x)
                    renderPixel(tracer, cam, s, x, y, out, count);
        }
        rayTotal += count;
    };
    const uint32_t threadCount = s.threads ? s.threads : std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> pool;
    for (uint32_t i = 0; i < threadCount; ++i) pool.emplace_back(worker);
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    const bool bar = s.progress && isatty(STDERR_FILENO);  // \r redraws only on a terminal, not in logs
    while (bar && doneTiles.load() < tiles) {
        drawProgress(double(doneTiles.load()) / tiles, elapsed());
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
    for (std::thread& t : pool) t.join();
    if (bar) {
        drawProgress(1.0, elapsed());
        fmt::print(stderr, "\n");
    }
    out.seconds = elapsed();
    out.rays = rayTotal.load();
    return out;
}

}  // namespace penumbra
