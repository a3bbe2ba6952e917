// Shared by the glTF loader tests (scene_test, gltf_rules_test, gltf_fuzz_test): a temporary
// directory, a small synthetic glTF (one triangle under a parent and a mirrored child, a textured
// material, a spot light, a camera) as JSON, .gltf with a data URI or .bin, and GLB bytes.
#pragma once
#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <stb_image_write.h>
#include <unistd.h>

#include "scene/animation.h"
#include "scene/scene.h"

namespace penumbra::test {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr float kEps = 1e-4f;

#define EXPECT_VEC3_NEAR(a, b)                                                             \
    do {                                                                                   \
        const glm::vec3 a_ = (a), b_ = (b);                                                \
        EXPECT_NEAR(a_.x, b_.x, kEps); EXPECT_NEAR(a_.y, b_.y, kEps); EXPECT_NEAR(a_.z, b_.z, kEps); \
    } while (0)

// A fresh directory per test, removed afterwards.
struct TempDir {
    fs::path path;
    TempDir() {
        static std::atomic<int> counter{0};
        path = fs::temp_directory_path() / ("penumbra_scene_test_" + std::to_string(getpid()) + "_" +
                                            std::to_string(counter++));
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    std::string file(const std::string& name) const { return (path / name).string(); }
};

inline void writeFile(const std::string& path, const void* data, size_t size) {
    std::ofstream f(path, std::ios::binary);
    f.write(static_cast<const char*>(data), std::streamsize(size));
}
inline void writeFile(const std::string& path, const std::string& text) { writeFile(path, text.data(), text.size()); }

inline std::string base64(const std::vector<uint8_t>& data) {
    static const char* tbl = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < data.size(); i += 3) {
        uint32_t v = uint32_t(data[i]) << 16;
        if (i + 1 < data.size()) v |= uint32_t(data[i + 1]) << 8;
        if (i + 2 < data.size()) v |= data[i + 2];
        out += tbl[(v >> 18) & 63];
        out += tbl[(v >> 12) & 63];
        out += i + 1 < data.size() ? tbl[(v >> 6) & 63] : '=';
        out += i + 2 < data.size() ? tbl[v & 63] : '=';
    }
    return out;
}

template <typename T>
inline void append(std::vector<uint8_t>& buf, const T& v) {
    const auto* p = reinterpret_cast<const uint8_t*>(&v);
    buf.insert(buf.end(), p, p + sizeof(T));
}

// Binary data of the test mesh: one triangle (0,0,0) (1,0,0) (0,1,0), no normals.
// [0,36) positions; [36,42) ushort indices (+2 pad); [44,56) normalized ubyte uvs, byteStride 4.
inline std::vector<uint8_t> testBin(uint16_t lastIndex = 2) {
    std::vector<uint8_t> bin;
    for (float f : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) append(bin, f);
    for (uint16_t i : {uint16_t(0), uint16_t(1), lastIndex, uint16_t(0)}) append(bin, i);
    for (uint8_t b : {0, 0, 7, 7, 255, 0, 7, 7, 0, 255, 7, 7}) bin.push_back(b);
    return bin;
}

// A 2x1 RGB PNG (red, then (0,128,255)); the loader must expand it to RGBA.
inline std::vector<uint8_t> testPng() {
    const uint8_t px[6] = {255, 0, 0, 0, 128, 255};
    std::vector<uint8_t> png;
    stbi_write_png_to_func(
        [](void* ctx, void* data, int size) {
            auto* out = static_cast<std::vector<uint8_t>*>(ctx);
            out->insert(out->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
        },
        &png, 2, 1, 3, px, 6);
    return png;
}

// The glTF document; `bufferUri` empty means the GLB-stored buffer.
inline json testGltf(const std::string& bufferUri, size_t binSize) {
    const double s = std::sqrt(0.5);
    json buffer = {{"byteLength", binSize}};
    if (!bufferUri.empty()) buffer["uri"] = bufferUri;
    return json{
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0, 2, 3}}}}},
        {"nodes",
         {{{"name", "parent"}, {"translation", {1, 2, 3}}, {"rotation", {0, s, 0, s}}, {"scale", {2, 2, 2}},
           {"mesh", 0}, {"children", {1}}},
          {{"name", "mirror"}, {"scale", {-1, 1, 1}}, {"mesh", 0}},
          {{"name", "lamp"}, {"translation", {0, 5, 0}}, {"rotation", {-s, 0, 0, s}},
           {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}},
          {{"name", "cam"}, {"translation", {0, 1, 10}}, {"camera", 0}}}},
        {"meshes",
         {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 2}}}, {"indices", 1}, {"material", 0}}}}}}},
        {"materials",
         {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.2, 0.1, 0.9}}, {"baseColorTexture", {{"index", 0}}}}},
           {"alphaMode", "MASK"}, {"alphaCutoff", 0.3}, {"doubleSided", true}}}},
        {"textures", {{{"source", 0}}}},
        {"images", {{{"uri", "data:image/png;base64," + base64(testPng())}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
           {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
          {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}},
          {{"bufferView", 2}, {"componentType", 5121}, {"normalized", true}, {"count", 3}, {"type", "VEC2"}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
          {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 6}},
          {{"buffer", 0}, {"byteOffset", 44}, {"byteLength", 12}, {"byteStride", 4}}}},
        {"buffers", {buffer}},
        {"cameras", {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}, {"zfar", 100}, {"aspectRatio", 1.5}}}}}},
        {"extensionsUsed", {"KHR_lights_punctual"}},
        {"extensions",
         {{"KHR_lights_punctual",
           {{"lights", {{{"name", "spot"}, {"type", "spot"}, {"color", {1, 0.5, 0.25}}, {"intensity", 20},
                         {"range", 15}, {"spot", {{"innerConeAngle", 0.3}, {"outerConeAngle", 0.6}}}}}}}}}},
    };
}

inline std::string writeGltf(const TempDir& dir, const std::string& name, const json& doc) {
    const std::string path = dir.file(name);
    writeFile(path, doc.dump(1));
    return path;
}

inline std::string dataUri(const std::vector<uint8_t>& bin) { return "data:application/octet-stream;base64," + base64(bin); }

inline std::vector<uint8_t> glbBytes(const json& doc, std::vector<uint8_t> bin) {
    std::string text = doc.dump();
    while (text.size() % 4) text += ' ';  // chunks are 4-byte aligned: JSON pads with spaces, BIN with zeros
    while (bin.size() % 4) bin.push_back(0);
    std::vector<uint8_t> out;
    append(out, uint32_t(0x46546C67));  // "glTF"
    append(out, uint32_t(2));
    append(out, uint32_t(12 + 8 + text.size() + 8 + bin.size()));
    append(out, uint32_t(text.size()));
    append(out, uint32_t(0x4E4F534A));  // "JSON"
    out.insert(out.end(), text.begin(), text.end());
    append(out, uint32_t(bin.size()));
    append(out, uint32_t(0x004E4942));  // "BIN\0"
    out.insert(out.end(), bin.begin(), bin.end());
    return out;
}

// The message of the SceneError `f` throws; fails the test when it throws nothing or something else.
inline std::string sceneError(const std::function<void()>& f) {
    try {
        f();
    } catch (const SceneError& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "expected SceneError, got another exception: " << e.what();
        return {};
    }
    ADD_FAILURE() << "expected SceneError, nothing was thrown";
    return {};
}

// Structural invariants every loaded scene must satisfy, whatever its content.
inline void expectConsistent(const Scene& s) {
    ASSERT_FALSE(s.materials.empty());
    EXPECT_EQ(s.materials[0].baseColor, glm::vec4(1.0f));
    ASSERT_GT(s.triangleCount(), 0u);
    EXPECT_EQ(s.indices.size() % 3, 0u);
    for (uint32_t i : s.indices) ASSERT_LT(i, s.vertices.size());
    uint32_t next = 0;
    for (const Draw& d : s.draws) {
        EXPECT_EQ(d.firstIndex, next);
        EXPECT_EQ(d.indexCount % 3, 0u);
        ASSERT_LT(d.material, s.materials.size());
        next += d.indexCount;
    }
    EXPECT_EQ(next, s.indices.size());
    for (const Material& m : s.materials) EXPECT_LT(m.baseColorTexture, int32_t(s.textures.size()));
    for (const Texture& t : s.textures) EXPECT_EQ(t.rgba8.size(), size_t(t.width) * t.height * 4);
    for (const Vertex& v : s.vertices) {
        ASSERT_TRUE(std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z));
        ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-3f);
    }
    ASSERT_FALSE(s.bounds.empty());
    // Meshes drawn per instance are in their own space: the bounds hold their world-space copies.
    const Scene world = worldSpaceScene(s, instanceTransforms(s, nodeWorldTransforms(s, 0.0, {})));
    for (const Vertex& v : world.vertices) {
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(v.position, s.bounds.min)));
        EXPECT_TRUE(glm::all(glm::lessThanEqual(v.position, s.bounds.max)));
    }
    for (const Light& l : s.lights) EXPECT_NEAR(glm::length(l.direction), 1.0f, 1e-3f);
}

// The scene's world-space geometry at rest (what loading baked before meshes were instanced).
inline Scene restWorld(const Scene& s) {
    return worldSpaceScene(s, instanceTransforms(s, nodeWorldTransforms(s, 0.0, {})));
}

// Counter-clockwise winding must agree with the vertex normals (true for flat test geometry).
inline void expectWindingMatchesNormals(const Scene& s) {
    for (size_t t = 0; t < s.indices.size(); t += 3) {
        const Vertex &a = s.vertices[s.indices[t]], &b = s.vertices[s.indices[t + 1]], &c = s.vertices[s.indices[t + 2]];
        const glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
        EXPECT_GT(glm::dot(face, a.normal), 0.0f) << "triangle " << t / 3;
    }
}


}  // namespace penumbra::test
