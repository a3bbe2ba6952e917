// Primitive topology for the glTF loader: strips and fans as triangle lists, line primitives as
// polylines, and smooth normals for a mesh without them.
#pragma once
#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace penumbra::gltf {

// Converts strips and fans to a plain triangle list (glTF 2.0 spec, section 3.7.2.1).
std::vector<uint32_t> toTriangleList(const std::vector<uint32_t>& idx, int mode);

// Line primitives as polylines (index lists): a LINE_STRIP is one, a LINE_LOOP one closed by its first
// point, and LINES segments are chained into one while each starts where the previous one ended.
std::vector<std::vector<uint32_t>> toPolylines(const std::vector<uint32_t>& idx, int mode);

// Area-weighted smooth normals (unnormalised): the face cross product has length 2 * area.
void generateNormals(std::vector<Vertex>& verts, const std::vector<uint32_t>& tris);

}  // namespace penumbra::gltf
