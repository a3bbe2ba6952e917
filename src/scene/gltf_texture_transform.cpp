#include "scene/gltf_texture_transform.h"

#include <cmath>

#include <fmt/format.h>

#include "scene/scene.h"

namespace penumbra::gltf {
namespace {

// glTF allows TEXCOORD_0 .. TEXCOORD_n; no exporter writes more than a handful.
constexpr int kMaxTexCoordSet = 7;

double number(const tinygltf::Value& v, const std::string& what) {
    if (!v.IsNumber()) throw SceneError(fmt::format("{}: expected a number", what));
    const double x = v.GetNumberAsDouble();
    if (!std::isfinite(x) || std::abs(x) > 1e9) throw SceneError(fmt::format("{}: {} is out of range", what, x));
    return x;
}

glm::vec2 pair(const tinygltf::Value& transform, const char* key, glm::vec2 fallback, const std::string& what) {
    if (!transform.Has(key)) return fallback;
    const tinygltf::Value& v = transform.Get(key);
    if (!v.IsArray() || v.ArrayLen() != 2) throw SceneError(fmt::format("{} {}: expected two numbers", what, key));
    return {float(number(v.Get(0), what + " " + key)), float(number(v.Get(1), what + " " + key))};
}

int texCoordSet(int set, const std::string& what) {
    if (set < 0 || set > kMaxTexCoordSet)
        throw SceneError(fmt::format("{}: texCoord {} is out of range [0, {}]", what, set, kMaxTexCoordSet));
    return set;
}

}  // namespace

glm::mat3x2 textureTransformMatrix(const glm::vec2& offset, float rotation, const glm::vec2& scale) {
    const float c = std::cos(rotation), s = std::sin(rotation);
    // Columns: the images of u, of v and of the origin.
    return glm::mat3x2(glm::vec2(scale.x * c, -scale.x * s), glm::vec2(scale.y * s, scale.y * c), offset);
}

UvTransform readUvTransform(const tinygltf::TextureInfo& info, const std::string& what) {
    UvTransform out;
    out.texCoord = texCoordSet(info.texCoord, what);
    const auto ext = info.extensions.find("KHR_texture_transform");
    if (ext == info.extensions.end()) return out;
    const tinygltf::Value& t = ext->second;
    const std::string where = what + " KHR_texture_transform";
    if (!t.IsObject()) throw SceneError(fmt::format("{}: expected an object", where));
    if (t.Has("texCoord")) {
        const tinygltf::Value& v = t.Get("texCoord");
        if (!v.IsInt()) throw SceneError(fmt::format("{} texCoord: expected an integer", where));
        out.texCoord = texCoordSet(v.GetNumberAsInt(), where);
    }
    const float rotation = t.Has("rotation") ? float(number(t.Get("rotation"), where + " rotation")) : 0.0f;
    out.matrix = textureTransformMatrix(pair(t, "offset", glm::vec2(0.0f), where), rotation,
                                        pair(t, "scale", glm::vec2(1.0f), where));
    return out;
}

}  // namespace penumbra::gltf
