// The reference path tracer's view of a Scene: an Embree 3 BVH over every triangle, and the surface
// data of a hit (position, normals, albedo from the base colour and its texture). Independent of the
// GPU renderer's code, but it makes the same visibility decisions as the rasterizer:
//  - a single-sided material is invisible from behind, both to rays from a viewer (camera, bounce)
//    and as a shadow caster, which only blocks the light when its front faces the light (the shadow
//    maps cull back faces; docs/techniques/shadows.md);
//  - alpha MASK texels under the cutoff are holes.
// Translucent surfaces, hair strands (Embree flat linear curves: ribbons facing the ray, of the
// strand's width, as the GPU's ribbons face each viewer) and alpha BLEND triangles, let light through:
//  - a ray from a viewer (camera, bounce) stops at one with probability alpha (the strand's opacity,
//    the material's alpha), otherwise passes it: in expectation the over operator, front to back;
//  - a shadow ray is not stopped by them but collects their transmittance, prod (1 - alpha) over
//    every one it crosses (what a deep shadow map stores), through an Embree filter callback.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include "reference/texture.h"
#include "scene/scene.h"

namespace penumbra::reference {

// The rays through the next pixel to the right (dirX) and below (dirY) of a camera ray: the texture
// footprint of a camera hit, as a GPU derives it from a 2x2 pixel quad.
struct PixelFootprint {
    glm::vec3 origin;
    glm::vec3 dirX, dirY;
};

struct Hit {
    float t = 0.0f;
    uint32_t triangle = 0;  // index into Scene::indices / 3 (a strand: its segment's first point)
    float u = 0.0f, v = 0.0f;  // barycentrics of vertices 1 and 2 (a strand: u along the segment)
    int32_t strand = -1;    // >= 0: the hit is on this Scene::strands entry
};

struct SurfacePoint {
    glm::vec3 position{0.0f};
    glm::vec3 geometricNormal{0.0f};  // unit, on the side the ray came from
    glm::vec3 shadingNormal{0.0f};    // interpolated vertex normal, turned towards the ray's origin
    glm::vec3 albedo{0.0f};           // linear
    int32_t strand = -1;              // >= 0: a hair strand (Kajiya-Kay, lit along its tangent)
    glm::vec3 tangent{0.0f};          // a strand's unit direction at the hit (its segment's)
};

// What a ray may pass through. `seed` makes the stochastic choice at translucent surfaces (one
// decision per primitive and seed, so a primitive Embree reports twice gets the same one);
// `skipStrand` is the strand a ray leaves (a ribbon facing the ray would hit its own strand);
// `opaqueOnly` looks through every translucent surface (the opaque surface behind them).
struct RayQuery {
    uint32_t seed = 0;
    int32_t skipStrand = -1;
    bool opaqueOnly = false;
};
class RayScene {
public:
    explicit RayScene(const Scene& scene);
    ~RayScene();
    RayScene(const RayScene&) = delete;
    RayScene& operator=(const RayScene&) = delete;

    // Nearest surface seen from `origin` along unit `dir` in (tmin, tmax); a translucent one stops
    // the ray with probability alpha (RayQuery).
    std::optional<Hit> intersect(const glm::vec3& origin, const glm::vec3& dir, float tmin, float tmax,
                                 const RayQuery& query = {}) const;
    // Fraction of a light's radiance that reaches `origin` along unit `dir` from tmax: 0 behind an
    // opaque caster, else prod (1 - alpha) over the translucent surfaces crossed, each counted once
    // (0 once it falls below kOpaqueTransmittance). A single-sided surface casts only when its front
    // faces the light. `skipStrand`: the strand the ray leaves.
    float transmittance(const glm::vec3& origin, const glm::vec3& dir, float tmax, int32_t skipStrand = -1) const;
    static constexpr float kOpaqueTransmittance = 1e-6f;
    // The scene has strands or BLEND triangles: a pixel's paths must each trace their own camera ray.
    bool translucent() const { return translucent_; }
    // The scene has single-sided triangles: a light's ray and a viewer's ray along the same line may
    // then see different surfaces (intersect() against transmittance()).
    bool singleSided() const { return singleSided_; }
    // The surface at a hit of a ray with direction `dir`. With a footprint (camera rays) the texture
    // is mip-mapped over it (texture.h says why); else bilinear at full resolution.
    SurfacePoint surface(const Hit& hit, const glm::vec3& dir, const PixelFootprint* footprint = nullptr) const;
    // A ray offset (world units) that clears the surface at p without skipping thin features.
    static float epsilon(const glm::vec3& p);

    // Per-triangle data the Embree filter reads (public for the C callback only).
    struct Triangles {
        const Scene* scene = nullptr;
        const std::vector<MipChain>* mips = nullptr;  // per texture
        std::vector<uint32_t> material;      // per triangle
        std::vector<glm::vec3> normal;       // per triangle, unnormalised cross(v1 - v0, v2 - v0): the front
        std::vector<uint32_t> filteredToTriangle;  // primID of the filtered geometry -> triangle
    };
    // Per strand segment (Embree curve primitive), for the strands' filter.
    struct Strands {
        const Scene* scene = nullptr;
        std::vector<uint32_t> firstPoint;  // primID -> the segment's first point in Scene::strandPoints
        std::vector<uint32_t> strand;      // primID -> Scene::strands index
    };

private:
    const Scene& scene_;
    Triangles tris_;
    Strands strands_;
    bool translucent_ = false, singleSided_ = false;
    // Embree ignores a curve's hits nearer than 2 radii to the ray origin (its self-intersection
    // avoidance, a build option), which would lose the strands next to a ray leaving a strand: every
    // ray starts this far behind its origin, with tmin moved as far.
    float curveBack_ = 0.0f;
    std::vector<MipChain> mips_;              // per Scene::textures entry
    std::vector<uint32_t> opaqueToTriangle_;  // primID of the unfiltered geometry -> triangle
    RTCDevice device_ = nullptr;
    RTCScene rtcScene_ = nullptr;
    uint32_t opaqueGeometry_ = RTC_INVALID_GEOMETRY_ID, filteredGeometry_ = RTC_INVALID_GEOMETRY_ID;
    uint32_t strandGeometry_ = RTC_INVALID_GEOMETRY_ID;

    uint32_t triangleOf(uint32_t geometry, uint32_t prim) const {
        return geometry == filteredGeometry_ ? tris_.filteredToTriangle[prim] : opaqueToTriangle_[prim];
    }
    void addGeometry(const std::vector<uint32_t>& triangles, bool filtered);
    void addStrands();
    SurfacePoint strandSurface(const Hit& hit, const glm::vec3& dir) const;
    std::optional<glm::vec2> planeUv(uint32_t triangle, const glm::vec3& o, const glm::vec3& d) const;
};

}  // namespace penumbra::reference
