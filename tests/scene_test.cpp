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

#include "gltf_test_util.h"
#include "scene/builders.h"
#include "scene/scene.h"

namespace fs = std::filesystem;
using nlohmann::json;
using namespace penumbra;
using namespace penumbra::test;

namespace {

void expectTestScene(const Scene& loaded) {
    expectConsistent(loaded);
    // The mesh is drawn by two nodes: stored once, drawn by two instances (after the empty static batch).
    EXPECT_EQ(loaded.vertices.size(), 3u);
    ASSERT_EQ(loaded.instances.size(), 3u);
    EXPECT_EQ(loaded.nodes.size(), 4u);
    EXPECT_EQ(loaded.nodes[1].parent, 0);
    // Its world-space copy at rest is what loading baked before.
    const Scene s = restWorld(loaded);
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
    EXPECT_EQ(builtinSceneNames(), (std::vector<std::string>{"cornell", "cornell-moving", "plane", "hair", "street", "room", "terrain"}));
}

// The GI suite's scenes (docs/evaluation.md): consistent, faces wound as their normals say.
TEST(BuiltinScenes, StreetAndRoom) {
    for (const std::string name : {"street", "room"}) {
        const Scene s = makeBuiltinScene(name);
        expectConsistent(s);
        expectWindingMatchesNormals(s);
        ASSERT_EQ(s.lights.size(), 1u);
        EXPECT_EQ(s.lights[0].type, name == "street" ? LightType::Directional : LightType::Point);
    }
    const Scene street = makeBuiltinScene("street");
    EXPECT_NEAR(street.bounds.max.x - street.bounds.min.x, 22.0f, 1e-4f);  // 10 m street, 6 m blocks
    EXPECT_NEAR(std::asin(-street.lights[0].direction.y), glm::radians(20.0f), glm::radians(1.0f)) << "low sun";
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
