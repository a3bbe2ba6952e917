#include "scene/gltf_checks.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cstring>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "scene/scene.h"

namespace penumbra::gltf {
namespace {

uint32_t le32(const uint8_t* p) { return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24; }

// Properties tinygltf stores in an int (object indices and enums).
bool isIntProperty(const std::string& key) {
    static const std::array<const char*, 28> keys{
        "indices", "material", "mode",   "mesh",    "camera",   "skin",      "scene",     "source",   "sampler",
        "index",   "texCoord", "buffer", "target",  "node",     "children",  "nodes",     "joints",   "skeleton",
        "input",   "output",   "light",  "bufferView", "byteStride", "componentType", "magFilter", "minFilter",
        "wrapS",   "wrapT"};
    return std::find(keys.begin(), keys.end(), key) != keys.end();
}

void checkInt(const nlohmann::json& v, const std::string& key) {
    if (!v.is_number_integer()) return;  // tinygltf ignores or rejects non-integers itself
    const bool fits = v.is_number_unsigned() ? v.get<uint64_t>() <= uint64_t(INT_MAX)
                                             : v.get<int64_t>() >= INT_MIN && v.get<int64_t>() <= INT_MAX;
    if (!fits) throw SceneError(fmt::format("invalid glTF: \"{}\": {} is out of range", key, v.dump()));
}

// Recursion is bounded: the depth was checked first.
void checkValue(const nlohmann::json& v) {
    if (v.is_array()) {
        for (const nlohmann::json& e : v) checkValue(e);
        return;
    }
    if (!v.is_object()) return;
    for (auto it = v.begin(); it != v.end(); ++it) {
        if (it.key() == "extras") continue;  // application data, not read
        if (isIntProperty(it.key())) {
            if (it.value().is_array())
                for (const nlohmann::json& e : it.value()) checkInt(e, it.key());
            else
                checkInt(it.value(), it.key());
        }
        checkValue(it.value());
    }
}

}  // namespace

size_t jsonNestingDepth(std::string_view json) {
    size_t depth = 0, deepest = 0;
    bool inString = false, escaped = false;
    for (char c : json) {
        if (inString) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') inString = false;
            continue;
        }
        if (c == '"') inString = true;
        else if (c == '[' || c == '{') deepest = std::max(deepest, ++depth);
        else if ((c == ']' || c == '}') && depth > 0) --depth;
    }
    return deepest;
}

std::string_view jsonText(const std::vector<uint8_t>& bytes, bool glb) {
    const auto* text = reinterpret_cast<const char*>(bytes.data());
    if (!glb) return {text, bytes.size()};
    if (bytes.size() < 20) throw SceneError("invalid glTF: the GLB header is cut short");
    const uint32_t version = le32(&bytes[4]), length = le32(&bytes[8]);
    const uint32_t jsonLength = le32(&bytes[12]), jsonType = le32(&bytes[16]);
    if (version != 2) throw SceneError(fmt::format("invalid glTF: GLB version {} (only version 2 exists)", version));
    if (length < 20 || length > bytes.size())
        throw SceneError(fmt::format("invalid glTF: the GLB header declares {} bytes, the file has {}", length,
                                     bytes.size()));
    if (jsonType != 0x4E4F534Au) throw SceneError("invalid glTF: the first GLB chunk is not JSON");
    if (jsonLength == 0 || jsonLength > length - 20)
        throw SceneError(fmt::format("invalid glTF: the GLB JSON chunk of {} bytes exceeds the file", jsonLength));
    return {text + 20, jsonLength};
}

void checkJson(std::string_view json) {
    const size_t depth = jsonNestingDepth(json);
    if (depth > kMaxJsonDepth)
        throw SceneError(fmt::format("invalid glTF: JSON nested {} levels deep (at most {})", depth, kMaxJsonDepth));
    const nlohmann::json doc = nlohmann::json::parse(json.begin(), json.end(), nullptr, false);
    if (doc.is_discarded()) return;  // tinygltf reports the syntax error with its position
    checkValue(doc);
}

}  // namespace penumbra::gltf
