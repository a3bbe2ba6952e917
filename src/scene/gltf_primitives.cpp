#include "scene/gltf_primitives.h"

#include <tiny_gltf.h>

namespace penumbra::gltf {

std::vector<uint32_t> toTriangleList(const std::vector<uint32_t>& idx, int mode) {
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        std::vector<uint32_t> out(idx.begin(), idx.begin() + ptrdiff_t(idx.size() / 3 * 3));
        return out;
    }
    std::vector<uint32_t> out;
    for (size_t i = 0; i + 2 < idx.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            // Every other strip triangle swaps its first two vertices to keep a consistent winding.
            const bool odd = (i & 1) != 0;
            out.insert(out.end(), {idx[odd ? i + 1 : i], idx[odd ? i : i + 1], idx[i + 2]});
        } else {  // fan
            out.insert(out.end(), {idx[i + 1], idx[i + 2], idx[0]});
        }
    }
    return out;
}

std::vector<std::vector<uint32_t>> toPolylines(const std::vector<uint32_t>& idx, int mode) {
    std::vector<std::vector<uint32_t>> out;
    if (mode != TINYGLTF_MODE_LINE) {
        if (idx.size() >= 2) out.push_back(idx);
        if (mode == TINYGLTF_MODE_LINE_LOOP && idx.size() >= 3) out.back().push_back(idx.front());
        return out;
    }
    for (size_t i = 0; i + 1 < idx.size(); i += 2) {
        if (out.empty() || out.back().back() != idx[i]) out.push_back({idx[i]});
        out.back().push_back(idx[i + 1]);
    }
    return out;
}

void generateNormals(std::vector<Vertex>& verts, const std::vector<uint32_t>& tris) {
    for (Vertex& v : verts) v.normal = glm::vec3(0.0f);
    for (size_t t = 0; t + 2 < tris.size(); t += 3) {
        Vertex &a = verts[tris[t]], &b = verts[tris[t + 1]], &c = verts[tris[t + 2]];
        const glm::vec3 n = glm::cross(b.position - a.position, c.position - a.position);
        a.normal += n;
        b.normal += n;
        c.normal += n;
    }
}

}  // namespace penumbra::gltf
