#include "scene/builders.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace penumbra {

void ensureDefaultMaterial(Scene& scene) {
    if (scene.materials.empty()) scene.materials.push_back(Material{});
}

uint32_t addMaterial(Scene& scene, const glm::vec3& rgb) {
    ensureDefaultMaterial(scene);
    Material m;
    m.baseColor = glm::vec4(rgb, 1.0f);
    scene.materials.push_back(m);
    return static_cast<uint32_t>(scene.materials.size() - 1);
}

void addTriangles(Scene& scene, std::span<const Vertex> vertices, std::span<const uint32_t> indices,
                  uint32_t material, bool mergeWithPrevious) {
    if (scene.vertices.size() + vertices.size() > std::numeric_limits<uint32_t>::max())
        throw SceneError("scene has more than 2^32 vertices");
    const auto base = static_cast<uint32_t>(scene.vertices.size());
    const auto first = static_cast<uint32_t>(scene.indices.size());
    scene.vertices.insert(scene.vertices.end(), vertices.begin(), vertices.end());
    for (uint32_t i : indices) scene.indices.push_back(base + i);
    const auto count = static_cast<uint32_t>(indices.size());
    if (count == 0) return;
    if (!scene.draws.empty() && mergeWithPrevious) {
        Draw& last = scene.draws.back();
        if (last.material == material && last.firstIndex + last.indexCount == first) {
            last.indexCount += count;
            return;
        }
    }
    scene.draws.push_back(Draw{first, count, material});
}

void mergeDrawsByMaterial(Scene& scene) {
    std::vector<Draw> draws = scene.draws;
    std::stable_sort(draws.begin(), draws.end(), [](const Draw& a, const Draw& b) { return a.material < b.material; });
    std::vector<uint32_t> indices;
    indices.reserve(scene.indices.size());
    std::vector<Draw> merged;
    for (const Draw& d : draws) {
        if (merged.empty() || merged.back().material != d.material)
            merged.push_back(Draw{uint32_t(indices.size()), 0, d.material});
        indices.insert(indices.end(), scene.indices.begin() + d.firstIndex,
                       scene.indices.begin() + d.firstIndex + d.indexCount);
        merged.back().indexCount += d.indexCount;
    }
    scene.indices = std::move(indices);
    scene.draws = std::move(merged);
}

void addQuad(Scene& scene, const glm::vec3& corner, const glm::vec3& edgeU, const glm::vec3& edgeV,
             uint32_t material) {
    const glm::vec3 n = glm::normalize(glm::cross(edgeU, edgeV));
    const std::array<Vertex, 4> v{{
        {corner, n, {0, 0}},
        {corner + edgeU, n, {1, 0}},
        {corner + edgeU + edgeV, n, {1, 1}},
        {corner + edgeV, n, {0, 1}},
    }};
    const std::array<uint32_t, 6> idx{0, 1, 2, 0, 2, 3};
    addTriangles(scene, v, idx, material);
}

void addBox(Scene& scene, const glm::vec3& center, const glm::vec3& halfExtents, float rotationYRadians,
            uint32_t material) {
    const float c = std::cos(rotationYRadians), s = std::sin(rotationYRadians);
    // Right-handed rotation about +Y (same as glm::rotate(angle, {0,1,0})), columns are the box axes.
    const glm::mat3 rot(glm::vec3(c, 0, -s), glm::vec3(0, 1, 0), glm::vec3(s, 0, c));
    for (int axis = 0; axis < 3; ++axis) {
        // (u, v, axis) is a cyclic permutation of (x, y, z), so cross(e_u, e_v) = e_axis.
        int u = (axis + 1) % 3, v = (axis + 2) % 3;
        for (float sign : {1.0f, -1.0f}) {
            if (sign < 0) std::swap(u, v);  // flips cross(edgeU, edgeV) to -e_axis
            glm::vec3 faceCenter(0.0f), eu(0.0f), ev(0.0f);
            faceCenter[axis] = sign * halfExtents[axis];
            eu[u] = 2.0f * halfExtents[u];
            ev[v] = 2.0f * halfExtents[v];
            const glm::vec3 corner = faceCenter - 0.5f * eu - 0.5f * ev;
            addQuad(scene, center + rot * corner, rot * eu, rot * ev, material);
        }
    }
}

void addStrand(Scene& scene, std::span<const glm::vec3> points, const Strand& style) {
    if (points.size() < 2) throw SceneError("a hair strand needs at least 2 points");
    if (scene.strandPoints.size() + points.size() > std::numeric_limits<uint32_t>::max())
        throw SceneError("scene has more than 2^32 strand points");
    Strand s = style;
    s.firstPoint = static_cast<uint32_t>(scene.strandPoints.size());
    s.pointCount = static_cast<uint32_t>(points.size());
    scene.strandPoints.insert(scene.strandPoints.end(), points.begin(), points.end());
    scene.strands.push_back(s);
}

}  // namespace penumbra
