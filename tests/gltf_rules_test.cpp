// The glTF loader against files that crashed it or loaded as if valid: JSON nested deeper than
// tinygltf's recursive parser survives, node chains deeper than a recursive visit survives under
// ASan, integers tinygltf truncates, glTF's component-type and alignment rules, GLB versions, a
// buffer URI naming a directory; and the warnings for what it drops or changes.
#include <string>

#include <gtest/gtest.h>

#include "gltf_test_util.h"
#include "scene/gltf_checks.h"
#include "scene/scene.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

json goodDoc() {
    const std::vector<uint8_t> bin = testBin();
    return testGltf(dataUri(bin), bin.size());
}

// The loader's error for `doc` must mention `word` (and be one line, with the path).
void expectRefused(const TempDir& dir, const json& doc, const std::string& name, const std::string& word) {
    const std::string path = writeGltf(dir, name, doc);
    const std::string msg = sceneError([&] { loadGltf(path); });
    EXPECT_NE(msg.find(word), std::string::npos) << name << ": " << msg;
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
}

bool hasWarning(const Scene& s, const std::string& word) {
    for (const std::string& w : s.warnings)
        if (w.find(word) != std::string::npos) return true;
    return false;
}

}  // namespace

TEST(GltfChecks, NestingDepthIgnoresBracketsInStrings) {
    EXPECT_EQ(gltf::jsonNestingDepth(R"({"a": "[[[{{", "b": [1, [2, {"c": "\"]]"}]]})"), 4u);
    EXPECT_EQ(gltf::jsonNestingDepth("[]"), 1u);
    EXPECT_EQ(gltf::jsonNestingDepth(std::string(100000, '[')), 100000u);  // iterative: no stack to overflow
}

// A 30 KB file nested 15000 deep overflowed the stack inside tinygltf's parser (SIGSEGV).
TEST(GltfChecks, DeepJsonIsRefusedBeforeParsing) {
    TempDir dir;
    const std::string deep = std::string(15000, '[') + std::string(15000, ']');
    std::string text = goodDoc().dump();
    text.insert(text.rfind('}'), R"(,"extras":)" + deep);
    writeFile(dir.file("deep.gltf"), text);
    const std::string msg = sceneError([&] { loadGltf(dir.file("deep.gltf")); });
    EXPECT_NE(msg.find("nested 15001 levels"), std::string::npos) << msg;

    // The same JSON in a GLB's JSON chunk (written as text: nlohmann's parser would recurse too).
    std::string padded = text;
    while (padded.size() % 4) padded += ' ';
    std::vector<uint8_t> glb;
    append(glb, uint32_t(0x46546C67));
    append(glb, uint32_t(2));
    append(glb, uint32_t(20 + padded.size()));
    append(glb, uint32_t(padded.size()));
    append(glb, uint32_t(0x4E4F534A));
    glb.insert(glb.end(), padded.begin(), padded.end());
    writeFile(dir.file("deep.glb"), glb.data(), glb.size());
    const std::string glbMsg = sceneError([&] { loadGltf(dir.file("deep.glb")); });
    EXPECT_NE(glbMsg.find("nested"), std::string::npos) << glbMsg;
}

// A recursive visit overflowed the stack under ASan at 1000 levels (the depth limit is 1024).
TEST(GltfChecks, ThousandDeepNodeChainLoads) {
    TempDir dir;
    json doc = goodDoc();
    constexpr int kDepth = 1000;
    json nodes = json::array();
    for (int i = 0; i < kDepth; ++i) {
        json n = {{"translation", {0.001, 0, 0}}};
        if (i + 1 < kDepth) n["children"] = {i + 1};
        else n["mesh"] = 0;
        nodes.push_back(n);
    }
    doc["nodes"] = nodes;
    doc["scenes"] = {{{"nodes", {0}}}};
    const Scene s = loadGltf(writeGltf(dir, "chain.gltf", doc));
    expectConsistent(s);
    ASSERT_EQ(s.vertices.size(), 3u);
    EXPECT_NEAR(s.vertices[0].position.x, kDepth * 0.001f, 1e-4f);  // every level's transform applied
}

TEST(GltfChecks, IntegersTinygltfWouldTruncateAreRefused) {
    TempDir dir;
    json doc = goodDoc();
    doc["meshes"][0]["primitives"][0]["indices"] = 4294967297ull;  // 2^32 + 1 read as 1 by tinygltf
    expectRefused(dir, doc, "index_2_32.gltf", "4294967297 is out of range");
    doc = goodDoc();
    doc["scenes"][0]["nodes"] = {0, 2, 4294967299ull};
    expectRefused(dir, doc, "node_2_32.gltf", "out of range");
    doc = goodDoc();
    doc["extras"] = {{"indices", 4294967297ull}};  // application data is not read
    EXPECT_NO_THROW(loadGltf(writeGltf(dir, "extras.gltf", doc)));
}

TEST(GltfChecks, AttributeComponentTypesFollowTheSpec) {
    TempDir dir;
    json doc = goodDoc();
    doc["accessors"][0]["componentType"] = 5120;  // BYTE positions (3 x 3 bytes fit the view)
    expectRefused(dir, doc, "byte_position.gltf", "without KHR_mesh_quantization");
    doc["extensionsUsed"].push_back("KHR_mesh_quantization");
    EXPECT_NO_THROW(loadGltf(writeGltf(dir, "byte_position_quantized.gltf", doc)));

    doc = goodDoc();
    doc["accessors"][2]["normalized"] = false;  // UNSIGNED_BYTE uvs must be normalized
    expectRefused(dir, doc, "ubyte_uv.gltf", "TEXCOORD_0");
}

TEST(GltfChecks, MisalignedBufferViewIsRefused) {
    TempDir dir;
    json doc = goodDoc();
    doc["bufferViews"][0]["byteOffset"] = 2;  // floats at byte 2 (still inside the buffer)
    expectRefused(dir, doc, "misaligned.gltf", "not aligned");
}

TEST(GltfChecks, GlbHeaderIsChecked) {
    TempDir dir;
    const std::vector<uint8_t> bin = testBin();
    std::vector<uint8_t> glb = glbBytes(testGltf("", bin.size()), bin);
    glb[4] = 3;  // version 3
    writeFile(dir.file("v3.glb"), glb.data(), glb.size());
    EXPECT_NE(sceneError([&] { loadGltf(dir.file("v3.glb")); }).find("GLB version 3"), std::string::npos);
    glb[4] = 2;
    glb[8] = 0xFF, glb[9] = 0xFF;  // declared length beyond the file
    writeFile(dir.file("long.glb"), glb.data(), glb.size());
    EXPECT_NE(sceneError([&] { loadGltf(dir.file("long.glb")); }).find("declares"), std::string::npos);
}

// Reading a directory as a buffer gave std::bad_alloc.
TEST(GltfChecks, BufferUriNamingADirectoryIsRefused) {
    TempDir dir;
    fs::create_directories(dir.path / "data.bin");
    const std::vector<uint8_t> bin = testBin();
    expectRefused(dir, testGltf("data.bin", bin.size()), "dir_buffer.gltf", "is a directory");
}

TEST(GltfWarnings, MissingTextureIsOneWarning) {
    TempDir dir;
    json doc = goodDoc();
    doc["images"][0]["uri"] = "missing.png";
    const Scene s = loadGltf(writeGltf(dir, "no_image.gltf", doc));
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("missing.png"), std::string::npos) << s.warnings[0];
    EXPECT_EQ(s.materials[1].baseColorTexture, -1);
}

TEST(GltfWarnings, OrthographicCameraIsSkippedWithAWarning) {
    TempDir dir;
    json doc = goodDoc();
    doc["cameras"].insert(doc["cameras"].begin(),
                          json{{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}});
    doc["nodes"][3]["camera"] = 1;  // the perspective camera is now camera 1
    doc["nodes"].push_back({{"camera", 0}});
    doc["scenes"][0]["nodes"] = {0, 2, 4, 3};  // the orthographic camera's node first
    const Scene s = loadGltf(writeGltf(dir, "ortho.gltf", doc));
    ASSERT_EQ(s.cameras.size(), 1u);  // --camera-index 0 is the perspective camera
    EXPECT_NEAR(s.cameras[0].fovy, 0.8f, 1e-5f);
    EXPECT_TRUE(hasWarning(s, "orthographic")) << ::testing::PrintToString(s.warnings);
}

TEST(GltfWarnings, NegativeLightValuesAreClampedWithAWarning) {
    TempDir dir;
    json doc = goodDoc();
    auto& light = doc["extensions"]["KHR_lights_punctual"]["lights"][0];
    light["intensity"] = -20;
    light["color"] = {1, -0.5, 0.25};
    const Scene s = loadGltf(writeGltf(dir, "negative.gltf", doc));
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].intensity, 0.0f);
    EXPECT_EQ(s.lights[0].color.y, 0.0f);
    EXPECT_TRUE(hasWarning(s, "intensity -20")) << ::testing::PrintToString(s.warnings);
    EXPECT_TRUE(hasWarning(s, "colour")) << ::testing::PrintToString(s.warnings);
    EXPECT_EQ(s.warnings.size(), 2u);
}

// 200000 node references: `count` distinct nodes on a grid, each with a mesh of two primitives (two
// materials, one double-sided, so the draws alternate as the nodes are visited).
static json manyNodes(int count) {
    json doc = goodDoc();
    doc["materials"].push_back({{"pbrMetallicRoughness", {{"baseColorFactor", {0.1, 0.8, 0.1, 1}}}}});
    json& prims = doc["meshes"][0]["primitives"];
    prims[0].erase("attributes");
    prims[0]["attributes"] = {{"POSITION", 0}};
    prims.push_back(prims[0]);
    prims[1]["material"] = 1;
    json nodes = json::array(), roots = json::array();
    for (int i = 0; i < count; ++i) {
        nodes.push_back({{"mesh", 0}, {"translation", {(i % 448) * 1.5, 0, (i / 448) * 1.5}}});
        roots.push_back(i);
    }
    doc["nodes"] = nodes;
    doc["scenes"] = {{{"nodes", roots}}};
    doc.erase("cameras");
    doc.erase("extensions");
    return doc;
}

// 200000 nodes draw one mesh: it is stored once and drawn as 200000 instances, one instanced draw per
// material in every pass (they alternated: 400000 draws before); the world-space copy the path tracer
// traces sorts the triangles by material.
TEST(GltfScale, TwoHundredThousandNodesDrawOncePerMaterial) {
    TempDir dir;
    const Scene loaded = loadGltf(writeGltf(dir, "many.gltf", manyNodes(200000)));
    EXPECT_EQ(loaded.triangleCount(), 2u);
    ASSERT_EQ(loaded.meshes.size(), 2u);
    EXPECT_EQ(loaded.meshes[1].drawCount, 2u);
    EXPECT_EQ(loaded.instances.size(), 200001u);
    for (size_t i = 1; i < loaded.instances.size(); ++i) ASSERT_EQ(loaded.instances[i].mesh, 1u);  // one run
    const Scene s = restWorld(loaded);
    EXPECT_EQ(s.triangleCount(), 400000u);
    ASSERT_EQ(s.draws.size(), 2u);
    EXPECT_EQ(s.draws[0].material, 1u);
    EXPECT_EQ(s.draws[1].material, 2u);
    EXPECT_EQ(s.draws[0].indexCount, 600000u);
    expectConsistent(s);
}

// One node listed 200000 times drew one triangle 200000 times over itself (minutes of shadow-map fill).
TEST(GltfScale, RepeatedNodeReferencesAreSkippedWithAWarning) {
    TempDir dir;
    json doc = goodDoc();
    doc["scenes"][0]["nodes"] = json::array();
    for (int i = 0; i < 200000; ++i) doc["scenes"][0]["nodes"].push_back(0);
    const Scene s = loadGltf(writeGltf(dir, "repeated.gltf", doc));
    EXPECT_EQ(restWorld(s).triangleCount(), 2u);  // node 0 and its child, once
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("199999 repeat(s) skipped"), std::string::npos) << s.warnings[0];
}
