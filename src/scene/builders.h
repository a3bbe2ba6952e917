// Helpers that append geometry and materials to a Scene: used by the procedural scenes, the glTF
// loader and the tests. Everything is world space, like the rest of Scene.
#pragma once
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace penumbra {

// Adds the default white material at index 0 if the scene has no material yet.
void ensureDefaultMaterial(Scene& scene);

// Appends an opaque single-sided material with base colour `rgb` (linear); returns its index.
// Ensures the default white material exists first, so the first call returns 1.
uint32_t addMaterial(Scene& scene, const glm::vec3& rgb);

// Appends triangles (indices relative to `vertices`) as one draw; merges with the previous draw
// when it has the same material and directly precedes it, to keep the draw count low.
void addTriangles(Scene& scene, std::span<const Vertex> vertices, std::span<const uint32_t> indices,
                  uint32_t material, bool mergeWithPrevious = true);

// Reorders the triangles so that each material's are contiguous, in material order (which also
// groups the cull modes, a material property): one draw per material. The glTF loader calls it, so
// a file of 200000 nodes over a few materials costs a few draw calls per pass, not 200000.
void mergeDrawsByMaterial(Scene& scene);

// Two triangles spanning corner, corner+edgeU, corner+edgeU+edgeV, corner+edgeV, counter-clockwise
// seen from the side normalize(cross(edgeU, edgeV)) points to. uv (0,0) at corner, (1,1) opposite.
void addQuad(Scene& scene, const glm::vec3& corner, const glm::vec3& edgeU, const glm::vec3& edgeV,
             uint32_t material);

// A box of 6 flat-shaded faces with outward normals, rotated about +Y (right-handed) around its centre.
void addBox(Scene& scene, const glm::vec3& center, const glm::vec3& halfExtents, float rotationYRadians,
            uint32_t material);

// Appends one hair strand: `points` (at least 2) with the width, opacity and colour of `style`
// (its firstPoint/pointCount are set here).
void addStrand(Scene& scene, std::span<const glm::vec3> points, const Strand& style);

}  // namespace penumbra
