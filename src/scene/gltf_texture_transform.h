// The texture coordinates a material's base-colour texture reads (internal to the glTF loader): the
// TEXCOORD_n set it names and its KHR_texture_transform. The loader applies the transform to the
// primitive's texture coordinates as it reads them: the transform is affine and texture coordinates
// are interpolated linearly (perspective-correct), so transforming the vertices equals transforming
// every sample, and the G-buffer, the path tracer, the RSM's flux and the LPV's injection, which all
// read Vertex::uv, see the same texels. (The base colour is the only texture penumbra reads.)
#pragma once
#include <string>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

namespace penumbra::gltf {

struct UvTransform {
    int texCoord = 0;           // TEXCOORD_n
    glm::mat3x2 matrix{1.0f};   // uv' = matrix * (u, v, 1): offset * rotation * scale
    bool identity() const { return matrix == glm::mat3x2(1.0f); }
    glm::vec2 apply(const glm::vec2& uv) const { return matrix * glm::vec3(uv, 1.0f); }
};

// KHR_texture_transform as its specification's example defines it (offset (0, 1), rotation pi/2,
// scale 0.5 maps the unit square onto the image's lower-left quadrant turned clockwise):
//   u' = sx cos(r) u + sy sin(r) v + ox,   v' = -sx sin(r) u + sy cos(r) v + oy.
glm::mat3x2 textureTransformMatrix(const glm::vec2& offset, float rotation, const glm::vec2& scale);

// The uv set and transform of a texture reference (`what` names it in errors). The extension's
// texCoord overrides the reference's. Throws SceneError for a set outside [0, 7] or a non-finite
// offset, rotation or scale (the texels would be NaN).
UvTransform readUvTransform(const tinygltf::TextureInfo& info, const std::string& what);

}  // namespace penumbra::gltf
