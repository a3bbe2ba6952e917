// The reference path tracer's view of a Scene: an Embree 3 BVH over every triangle, and the surface
// data of a hit (position, normals, albedo from the base colour and its texture). Independent of the
// GPU renderer's code, but it makes the same visibility decisions as the rasterizer:
//  - a single-sided material is invisible from behind, both to rays from a viewer (camera, bounce)
//    and as a shadow caster, which only blocks the light when its front faces the light (the shadow
//    maps cull back faces; README "Shadows");
//  - alpha MASK (and BLEND, which the G-buffer and shadow passes draw like MASK) texels under the
//    cutoff are holes.
// Hair strands are not traced (they are the deep-shadow-map module's business).
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
    uint32_t triangle = 0;  // index into Scene::indices / 3
    float u = 0.0f, v = 0.0f;  // barycentrics of vertices 1 and 2
};

struct SurfacePoint {
    glm::vec3 position{0.0f};
    glm::vec3 geometricNormal{0.0f};  // unit, on the side the ray came from
    glm::vec3 shadingNormal{0.0f};    // interpolated vertex normal, turned towards the ray's origin
    glm::vec3 albedo{0.0f};           // linear
};

class RayScene {
public:
    explicit RayScene(const Scene& scene);
    ~RayScene();
    RayScene(const RayScene&) = delete;
    RayScene& operator=(const RayScene&) = delete;

    // Nearest surface seen from `origin` along unit `dir` in (tmin, tmax).
    std::optional<Hit> intersect(const glm::vec3& origin, const glm::vec3& dir, float tmin, float tmax) const;
    // Whether a shadow caster lies on the segment from `origin` towards a light along unit `dir`, up
    // to tmax. A single-sided surface blocks only when its front faces the light.
    bool occluded(const glm::vec3& origin, const glm::vec3& dir, float tmax) const;
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

private:
    const Scene& scene_;
    Triangles tris_;
    std::vector<MipChain> mips_;              // per Scene::textures entry
    std::vector<uint32_t> opaqueToTriangle_;  // primID of the unfiltered geometry -> triangle
    RTCDevice device_ = nullptr;
    RTCScene rtcScene_ = nullptr;
    uint32_t opaqueGeometry_ = RTC_INVALID_GEOMETRY_ID, filteredGeometry_ = RTC_INVALID_GEOMETRY_ID;

    uint32_t triangleOf(uint32_t geometry, uint32_t prim) const {
        return geometry == filteredGeometry_ ? tris_.filteredToTriangle[prim] : opaqueToTriangle_[prim];
    }
    void addGeometry(const std::vector<uint32_t>& triangles, bool filtered);
    std::optional<glm::vec2> planeUv(uint32_t triangle, const glm::vec3& o, const glm::vec3& d) const;
};

}  // namespace penumbra::reference
