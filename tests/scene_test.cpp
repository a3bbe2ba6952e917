// CPU-only tests of scene loading: a synthetic glTF written here (as .gltf and .glb), malformed
// inputs, the built-in scenes, the geometry builders and the real sample models in ../shared/assets.
#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <stb_image_write.h>
#include <unistd.h>

#include "scene/builders.h"
#include "scene/scene.h"

namespace fs = std::filesystem;
using nlohmann::json;
using namespace penumbra;

namespace {

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

void writeFile(const std::string& path, const void* data, size_t size) {
    std::ofstream f(path, std::ios::binary);
    f.write(static_cast<const char*>(data), std::streamsize(size));
}
void writeFile(const std::string& path, const std::string& text) { writeFile(path, text.data(), text.size()); }

std::string base64(const std::vector<uint8_t>& data) {
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
void append(std::vector<uint8_t>& buf, const T& v) {
    const auto* p = reinterpret_cast<const uint8_t*>(&v);
    buf.insert(buf.end(), p, p + sizeof(T));
}

// Binary data of the test mesh: one triangle (0,0,0) (1,0,0) (0,1,0), no normals.
// [0,36) positions; [36,42) ushort indices (+2 pad); [44,56) normalized ubyte uvs, byteStride 4.
std::vector<uint8_t> testBin(uint16_t lastIndex = 2) {
    std::vector<uint8_t> bin;
    for (float f : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) append(bin, f);
    for (uint16_t i : {uint16_t(0), uint16_t(1), lastIndex, uint16_t(0)}) append(bin, i);
    for (uint8_t b : {0, 0, 7, 7, 255, 0, 7, 7, 0, 255, 7, 7}) bin.push_back(b);
    return bin;
}

// A 2x1 RGB PNG (red, then (0,128,255)); the loader must expand it to RGBA.
std::vector<uint8_t> testPng() {
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
json testGltf(const std::string& bufferUri, size_t binSize) {
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

std::string writeGltf(const TempDir& dir, const std::string& name, const json& doc) {
    const std::string path = dir.file(name);
    writeFile(path, doc.dump(1));
    return path;
}

std::string dataUri(const std::vector<uint8_t>& bin) { return "data:application/octet-stream;base64," + base64(bin); }

std::vector<uint8_t> glbBytes(const json& doc, std::vector<uint8_t> bin) {
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
std::string sceneError(const std::function<void()>& f) {
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
void expectConsistent(const Scene& s) {
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
    for (const Vertex& v : s.vertices) {
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(v.position, s.bounds.min)));
        EXPECT_TRUE(glm::all(glm::lessThanEqual(v.position, s.bounds.max)));
    }
    for (const Light& l : s.lights) EXPECT_NEAR(glm::length(l.direction), 1.0f, 1e-3f);
}

// Counter-clockwise winding must agree with the vertex normals (true for flat test geometry).
void expectWindingMatchesNormals(const Scene& s) {
    for (size_t t = 0; t < s.indices.size(); t += 3) {
        const Vertex &a = s.vertices[s.indices[t]], &b = s.vertices[s.indices[t + 1]], &c = s.vertices[s.indices[t + 2]];
        const glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
        EXPECT_GT(glm::dot(face, a.normal), 0.0f) << "triangle " << t / 3;
    }
}

void expectTestScene(const Scene& s) {
    expectConsistent(s);
    ASSERT_EQ(s.vertices.size(), 6u);
    ASSERT_EQ(s.triangleCount(), 2u);
    ASSERT_EQ(s.draws.size(), 1u);  // same material, contiguous: merged
    EXPECT_EQ(s.draws[0].material, 1u);
    // "parent": T(1,2,3) * R_y(90deg) * S(2); local +z becomes world +x.
    EXPECT_VEC3_NEAR(s.vertices[0].position, glm::vec3(1, 2, 3));
    EXPECT_VEC3_NEAR(s.vertices[1].position, glm::vec3(1, 2, 1));
    EXPECT_VEC3_NEAR(s.vertices[2].position, glm::vec3(1, 4, 3));
    // "mirror" (child, scale x -1): mirrored, so its winding must be flipped to stay front-facing.
    EXPECT_VEC3_NEAR(s.vertices[4].position, glm::vec3(1, 2, 5));
    EXPECT_EQ(s.indices[3], 3u);
    EXPECT_EQ(s.indices[4], 5u);
    EXPECT_EQ(s.indices[5], 4u);
    for (const Vertex& v : s.vertices) EXPECT_VEC3_NEAR(v.normal, glm::vec3(1, 0, 0));  // generated
    expectWindingMatchesNormals(s);
    EXPECT_NEAR(s.vertices[1].uv.x, 1.0f, kEps);  // normalized ubyte 255 -> 1
    EXPECT_NEAR(s.vertices[2].uv.y, 1.0f, kEps);
    EXPECT_VEC3_NEAR(s.bounds.min, glm::vec3(1, 2, 1));
    EXPECT_VEC3_NEAR(s.bounds.max, glm::vec3(1, 4, 5));

    ASSERT_EQ(s.materials.size(), 2u);
    const Material& m = s.materials[1];
    EXPECT_NEAR(m.baseColor.r, 0.8f, kEps);
    EXPECT_NEAR(m.baseColor.a, 0.9f, kEps);
    EXPECT_EQ(m.alphaMode, AlphaMode::Mask);
    EXPECT_NEAR(m.alphaCutoff, 0.3f, kEps);
    EXPECT_TRUE(m.doubleSided);
    ASSERT_EQ(m.baseColorTexture, 0);
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_EQ(s.textures[0].width, 2u);
    EXPECT_EQ(s.textures[0].height, 1u);
    EXPECT_EQ(s.textures[0].rgba8, (std::vector<uint8_t>{255, 0, 0, 255, 0, 128, 255, 255}));

    ASSERT_EQ(s.lights.size(), 1u);
    const Light& l = s.lights[0];
    EXPECT_EQ(l.type, LightType::Spot);
    EXPECT_VEC3_NEAR(l.position, glm::vec3(0, 5, 0));
    EXPECT_VEC3_NEAR(l.direction, glm::vec3(0, -1, 0));  // node -Z rotated -90deg about x
    EXPECT_VEC3_NEAR(l.color, glm::vec3(1, 0.5f, 0.25f));
    EXPECT_NEAR(l.intensity, 20.0f, kEps);
    EXPECT_NEAR(l.range, 15.0f, kEps);
    EXPECT_NEAR(l.innerConeAngle, 0.3f, kEps);
    EXPECT_NEAR(l.outerConeAngle, 0.6f, kEps);
    EXPECT_EQ(l.name, "spot");

    ASSERT_EQ(s.cameras.size(), 1u);
    const Camera& c = s.cameras[0];
    EXPECT_VEC3_NEAR(c.eye, glm::vec3(0, 1, 10));
    EXPECT_VEC3_NEAR(glm::normalize(c.target - c.eye), glm::vec3(0, 0, -1));
    EXPECT_VEC3_NEAR(c.up, glm::vec3(0, 1, 0));
    EXPECT_NEAR(c.fovy, 0.8f, kEps);
    EXPECT_NEAR(c.znear, 0.1f, kEps);
    EXPECT_NEAR(c.zfar, 100.0f, kEps);
}

TEST(GltfLoader, LoadsGltfWithDataUri) {
    TempDir dir;
    const std::vector<uint8_t> bin = testBin();
    const Scene s = loadGltf(writeGltf(dir, "test.gltf", testGltf(dataUri(bin), bin.size())));
    EXPECT_EQ(s.name, "test");
    expectTestScene(s);
}

TEST(GltfLoader, LoadsGltfWithBinFile) {
    TempDir dir;
    const std::vector<uint8_t> bin = testBin();
    writeFile(dir.file("test.bin"), bin.data(), bin.size());
    expectTestScene(loadGltf(writeGltf(dir, "test.gltf", testGltf("test.bin", bin.size()))));
}

TEST(GltfLoader, LoadsGlb) {
    TempDir dir;
    const std::vector<uint8_t> bin = testBin();
    const std::vector<uint8_t> glb = glbBytes(testGltf("", bin.size()), bin);
    writeFile(dir.file("test.glb"), glb.data(), glb.size());
    expectTestScene(loadGltf(dir.file("test.glb")));
}

TEST(GltfLoader, BadInputThrowsSceneError) {
    TempDir dir;
    const std::vector<uint8_t> bin = testBin();
    const json good = testGltf(dataUri(bin), bin.size());
    auto expectFails = [&](const std::string& path, const std::string& what) {
        const std::string msg = sceneError([&] { loadGltf(path); });
        EXPECT_NE(msg.find(path), std::string::npos) << what << ": message lacks the path: " << msg;
        EXPECT_EQ(msg.find('\n'), std::string::npos) << what << ": message is not one line: " << msg;
    };

    expectFails(dir.file("missing.gltf"), "missing file");
    EXPECT_EQ(sceneError([&] { loadScene(dir.file("missing.gltf")); }), "scene file not found: " + dir.file("missing.gltf"));

    std::mt19937 rng(42);
    std::vector<uint8_t> garbage(4096);
    for (uint8_t& b : garbage) b = uint8_t(rng());
    for (const char* name : {"garbage.gltf", "garbage.glb"}) {
        writeFile(dir.file(name), garbage.data(), garbage.size());
        expectFails(dir.file(name), name);
    }
    std::memcpy(garbage.data(), "glTF", 4);  // GLB magic, garbage header and chunks
    writeFile(dir.file("garbage_magic.glb"), garbage.data(), garbage.size());
    expectFails(dir.file("garbage_magic.glb"), "garbage with GLB magic");

    const std::string text = good.dump(1);
    writeFile(dir.file("truncated.gltf"), text.substr(0, text.size() / 2));
    expectFails(dir.file("truncated.gltf"), "truncated JSON");

    const std::vector<uint8_t> glb = glbBytes(good, bin);
    writeFile(dir.file("truncated.glb"), glb.data(), glb.size() - 40);
    expectFails(dir.file("truncated.glb"), "truncated GLB");

    json doc = good;
    doc["accessors"][1]["count"] = 1000;  // index accessor runs past its bufferView and buffer
    expectFails(writeGltf(dir, "index_past_end.gltf", doc), "index accessor past buffer end");

    doc = testGltf("missing.bin", bin.size());
    expectFails(writeGltf(dir, "missing_bin.gltf", doc), "missing external buffer");

    doc = good;
    doc["bufferViews"][0]["byteLength"] = 4000;  // bufferView past the end of its buffer
    expectFails(writeGltf(dir, "view_past_end.gltf", doc), "bufferView past buffer end");

    doc = good;
    doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 42;
    expectFails(writeGltf(dir, "bad_accessor.gltf", doc), "missing accessor");

    doc = testGltf(dataUri(testBin(7)), bin.size());  // index value 7 with 3 vertices
    expectFails(writeGltf(dir, "index_out_of_range.gltf", doc), "index out of range");

    doc = good;
    doc["nodes"][1]["children"] = {0};  // parent -> mirror -> parent
    expectFails(writeGltf(dir, "cycle.gltf", doc), "node cycle");

    doc = good;
    doc["meshes"][0]["primitives"][0]["mode"] = 0;  // points only: skipped, leaving nothing to draw
    expectFails(writeGltf(dir, "no_triangles.gltf", doc), "no triangles or lines");
}

TEST(GltfLoader, MissingImageLoadsUntextured) {
    TempDir dir;
    const std::vector<uint8_t> bin = testBin();
    json doc = testGltf(dataUri(bin), bin.size());
    doc["images"][0]["uri"] = "missing.png";
    const Scene s = loadGltf(writeGltf(dir, "no_image.gltf", doc));
    expectConsistent(s);
    EXPECT_EQ(s.materials[1].baseColorTexture, -1);
    EXPECT_TRUE(s.textures.empty());
}

TEST(SceneLoading, UnknownBuiltinNameListsBuiltins) {
    const std::string msg = sceneError([] { loadScene("nosuchscene"); });
    EXPECT_NE(msg.find("nosuchscene"), std::string::npos) << msg;
    EXPECT_NE(msg.find("cornell"), std::string::npos) << msg;
    EXPECT_NE(msg.find("plane"), std::string::npos) << msg;
    sceneError([] { makeBuiltinScene("nosuchscene"); });
}

TEST(BuiltinScenes, Cornell) {
    const Scene s = loadScene("cornell");
    expectConsistent(s);
    expectWindingMatchesNormals(s);  // walls face inward, boxes outward, all counter-clockwise
    EXPECT_VEC3_NEAR(s.bounds.min, glm::vec3(-1, 0, -1));
    EXPECT_VEC3_NEAR(s.bounds.max, glm::vec3(1, 2, 1));
    auto findMaterial = [&](glm::vec3 rgb) {
        for (size_t i = 0; i < s.materials.size(); ++i)
            if (glm::length(glm::vec3(s.materials[i].baseColor) - rgb) < 1e-4f) return uint32_t(i);
        ADD_FAILURE() << "material not found";
        return 0u;
    };
    const uint32_t red = findMaterial({0.63f, 0.065f, 0.05f});
    const uint32_t green = findMaterial({0.14f, 0.45f, 0.091f});
    int redVerts = 0, greenVerts = 0;
    for (const Draw& d : s.draws) {
        for (uint32_t i = d.firstIndex; i < d.firstIndex + d.indexCount; ++i) {
            const Vertex& v = s.vertices[s.indices[i]];
            if (d.material == red) {
                EXPECT_NEAR(v.position.x, -1.0f, kEps);
                EXPECT_VEC3_NEAR(v.normal, glm::vec3(1, 0, 0));
                ++redVerts;
            } else if (d.material == green) {
                EXPECT_NEAR(v.position.x, 1.0f, kEps);
                EXPECT_VEC3_NEAR(v.normal, glm::vec3(-1, 0, 0));
                ++greenVerts;
            }
        }
    }
    EXPECT_EQ(redVerts, 6);
    EXPECT_EQ(greenVerts, 6);
    EXPECT_EQ(s.triangleCount(), 5u * 2 + 2u * 12);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, LightType::Spot);
    EXPECT_VEC3_NEAR(s.lights[0].position, glm::vec3(0, 1.9f, 0));
    EXPECT_VEC3_NEAR(s.lights[0].direction, glm::vec3(0, -1, 0));
    EXPECT_NEAR(s.lights[0].outerConeAngle, glm::radians(65.0f), kEps);
    EXPECT_NEAR(s.lights[0].innerConeAngle, glm::radians(50.0f), kEps);
    ASSERT_EQ(s.cameras.size(), 1u);
    EXPECT_VEC3_NEAR(s.cameras[0].eye, glm::vec3(0, 1, 3.6f));
    EXPECT_NEAR(s.cameras[0].fovy, glm::radians(40.0f), kEps);
    EXPECT_GT(s.cameras[0].zfar, 3.6f + 1.0f);  // derived: sees the back wall
}

TEST(BuiltinScenes, Plane) {
    const Scene s = makeBuiltinScene("plane");
    expectConsistent(s);
    expectWindingMatchesNormals(s);
    EXPECT_VEC3_NEAR(s.bounds.min, glm::vec3(-10, 0, -10));
    EXPECT_VEC3_NEAR(s.bounds.max, glm::vec3(10, 0, 10));
    EXPECT_VEC3_NEAR(s.vertices[0].normal, glm::vec3(0, 1, 0));
    EXPECT_NEAR(s.materials[s.draws[0].material].baseColor.g, 0.5f, kEps);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, LightType::Directional);
    EXPECT_VEC3_NEAR(s.lights[0].direction, glm::vec3(0, -1, 0));
    ASSERT_EQ(s.cameras.size(), 1u);
    EXPECT_GT(s.cameras[0].eye.y, 0.0f);
    EXPECT_LT(glm::normalize(s.cameras[0].target - s.cameras[0].eye).y, -0.99f);
    EXPECT_EQ(builtinSceneNames(), (std::vector<std::string>{"cornell", "plane", "hair"}));
}

TEST(Builders, BoxHasOutwardFacesAndRotates) {
    Scene s;
    const uint32_t mat = addMaterial(s, {0.2f, 0.3f, 0.4f});
    EXPECT_EQ(mat, 1u);  // 0 is the default white
    const glm::vec3 center(1, 2, 3);
    addBox(s, center, {1, 2, 3}, glm::radians(90.0f), mat);
    s.computeBounds();
    expectConsistent(s);
    expectWindingMatchesNormals(s);
    EXPECT_EQ(s.triangleCount(), 12u);
    EXPECT_EQ(s.draws.size(), 1u);
    for (const Vertex& v : s.vertices) EXPECT_GT(glm::dot(v.normal, v.position - center), 0.0f);
    // Rotating 90 degrees about y swaps the x and z extents.
    EXPECT_VEC3_NEAR(s.bounds.min, center - glm::vec3(3, 2, 1));
    EXPECT_VEC3_NEAR(s.bounds.max, center + glm::vec3(3, 2, 1));
}

TEST(Defaults, AddsSunAndFramingCamera) {
    Scene s;
    addQuad(s, {-1, 0, -1}, {0, 0, 2}, {2, 0, 0}, addMaterial(s, glm::vec3(1)));
    s.computeBounds();
    addDefaultsIfMissing(s);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, LightType::Directional);
    EXPECT_NEAR(s.lights[0].intensity, 3.0f, kEps);
    EXPECT_VEC3_NEAR(s.lights[0].direction, glm::normalize(glm::vec3(-0.4f, -1, -0.3f)));
    ASSERT_EQ(s.cameras.size(), 1u);
    const Camera& c = s.cameras[0];
    EXPECT_VEC3_NEAR(c.target, s.bounds.center());
    EXPECT_GT(c.eye.y, s.bounds.max.y);  // from above
    EXPECT_GT(c.zfar, glm::length(c.eye - c.target) + s.bounds.radius());
    addDefaultsIfMissing(s);  // idempotent
    EXPECT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.cameras.size(), 1u);
}

// ---- the real sample models in ../shared/assets ----

fs::path assetsDir() {
#ifdef PENUMBRA_SOURCE_DIR
    return fs::path(PENUMBRA_SOURCE_DIR) / ".." / "shared" / "assets";
#else
    return {};
#endif
}

Scene loadAsset(const std::string& relative) {
    const Scene s = loadGltf((assetsDir() / relative).string());
    expectConsistent(s);
    EXPECT_LT(s.bounds.radius(), 1e5f);
    EXPECT_GT(s.bounds.radius(), 1e-3f);
    return s;
}

class SampleModels : public ::testing::Test {
protected:
    void SetUp() override {
        if (assetsDir().empty() || !fs::is_directory(assetsDir()))
            GTEST_SKIP() << "no ../shared/assets next to the source tree";
    }
};

TEST_F(SampleModels, Duck) {
    const Scene s = loadAsset("Duck/glTF/Duck.gltf");
    EXPECT_EQ(s.cameras.size(), 1u);
    ASSERT_EQ(s.materials.size(), 2u);
    ASSERT_GE(s.materials[1].baseColorTexture, 0);  // DuckCM.png
    EXPECT_GT(s.textures[0].width, 0u);
}

TEST_F(SampleModels, Suzanne) {
    const Scene s = loadAsset("Suzanne/glTF/Suzanne.gltf");
    EXPECT_TRUE(s.cameras.empty());
    EXPECT_TRUE(s.lights.empty());
    const Scene withDefaults = loadScene((assetsDir() / "Suzanne/glTF/Suzanne.gltf").string());
    ASSERT_EQ(withDefaults.cameras.size(), 1u);
    ASSERT_EQ(withDefaults.lights.size(), 1u);
    EXPECT_EQ(withDefaults.lights[0].name, "sun");
}

TEST_F(SampleModels, VirtualCity) {
    const Scene s = loadAsset("VC/glTF/VC.gltf");
    EXPECT_EQ(s.cameras.size(), 14u);
    EXPECT_EQ(s.triangleCount(), 8383u);  // counted independently from the JSON
    EXPECT_FALSE(s.textures.empty());
    for (const Camera& c : s.cameras) {
        EXPECT_GT(c.fovy, 0.0f);
        EXPECT_NEAR(glm::length(c.up), 1.0f, 1e-3f);
    }
}

TEST_F(SampleModels, AlphaBlendModeTest) {
    const Scene s = loadAsset("AlphaBlendModeTest/glTF/AlphaBlendModeTest.gltf");
    int mask = 0, blend = 0;
    for (const Material& m : s.materials) {
        mask += m.alphaMode == AlphaMode::Mask;
        blend += m.alphaMode == AlphaMode::Blend;
    }
    EXPECT_GT(mask, 0);
    EXPECT_GT(blend, 0);
}

}  // namespace
