// In-process mutation fuzzer of the glTF/GLB loader (fixed seeds): mutants of the small test file
// (gltf_test_util.h) as .gltf with a data URI, .gltf with a .bin beside it, and .glb. Structural
// mutations edit the JSON (indices, accessors, buffer views, buffers, URIs, nesting, deleted keys),
// byte mutations flip, insert and cut bytes of the JSON text and of the GLB header and chunks; the
// images are left intact (decoders are not under test here). Every mutant must end in SceneError
// with a one-line message, or in a scene that satisfies the loader's invariants.
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "gltf_test_util.h"
#include "scene/scene.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

constexpr int kStructuralMutants = 1200;
constexpr int kByteMutants = 900;

struct Outcome {
    int loaded = 0, refused = 0;
};

// Loads `path`; a failure of the contract is a test failure naming the mutant.
void loadMutant(const std::string& path, const std::string& mutation, Outcome& out) {
    try {
        const Scene s = loadGltf(path);
        ++out.loaded;
        // A scene that loads must be one the renderer can take.
        for (uint32_t i : s.indices) ASSERT_LT(i, s.vertices.size()) << mutation;
        size_t covered = 0;
        for (const Draw& d : s.draws) {
            ASSERT_LT(d.material, s.materials.size()) << mutation;
            covered += d.indexCount;
        }
        ASSERT_EQ(covered, s.indices.size()) << mutation;
        for (const Vertex& v : s.vertices)
            ASSERT_TRUE(std::isfinite(v.position.x + v.position.y + v.position.z)) << mutation;
        for (const Material& m : s.materials) ASSERT_LT(m.baseColorTexture, int32_t(s.textures.size())) << mutation;
    } catch (const SceneError& e) {
        ++out.refused;
        const std::string msg = e.what();
        EXPECT_FALSE(msg.empty()) << mutation;
        EXPECT_EQ(msg.find('\n'), std::string::npos) << mutation << ": " << msg;
    } catch (const std::exception& e) {
        ADD_FAILURE() << mutation << ": not a SceneError: " << e.what();
    }
}

// Values that break assumptions: negative, zero, off by one, 16/32-bit edges, 2^32 + 1, huge.
json oddInteger(std::mt19937& rng) {
    static const std::vector<json> values{-1, 0, 1, 2, 3, 4, 5, 7, 255, 256, 65535, 65536, 2147483647,
                                          2147483648ull, 4294967295ull, 4294967297ull, -2147483648ll,
                                          1ull << 40, 1e300, 0.5, "x", nullptr, json::array(), json::object()};
    return values[rng() % values.size()];
}

// One structural edit of the document (never of its images).
std::string mutateJson(json& doc, std::mt19937& rng) {
    static const std::vector<std::pair<std::string, std::vector<std::string>>> fields{
        {"accessors", {"bufferView", "byteOffset", "componentType", "count", "type", "normalized", "sparse"}},
        {"bufferViews", {"buffer", "byteOffset", "byteLength", "byteStride"}},
        {"buffers", {"byteLength", "uri"}},
        {"nodes", {"mesh", "camera", "children", "matrix", "scale", "translation", "rotation"}},
        {"meshes", {"primitives"}},
        {"materials", {"alphaMode", "alphaCutoff", "pbrMetallicRoughness"}},
        {"scenes", {"nodes"}},
        {"textures", {"source", "sampler"}},
        {"cameras", {"type", "perspective"}},
    };
    const auto& [array, keys] = fields[rng() % fields.size()];
    json& items = doc[array];
    if (!items.is_array() || items.empty()) return "empty " + array;
    json& item = items[rng() % items.size()];
    const std::string key = keys[rng() % keys.size()];
    switch (rng() % 6) {
        case 0: item[key] = oddInteger(rng); return array + "." + key + " = " + item[key].dump();
        case 1: item.erase(key); return "delete " + array + "." + key;
        case 2: {  // nest the value deeply (within the depth limit and beyond it)
            json v = item.contains(key) ? item[key] : json(1);
            const int depth = (rng() % 2) ? 40 : 80;
            for (int i = 0; i < depth; ++i) v = json::array({v});
            item[key] = v;
            return array + "." + key + " nested " + std::to_string(depth);
        }
        case 3: {  // a URI that is missing, a directory, corrupt, or escapes the directory
            static const std::vector<std::string> uris{"missing.bin", "subdir", "/", "", "..",
                                                      "data:application/octet-stream;base64,!!!",
                                                      "data:application/octet-stream;base64,AAEC"};
            if (doc["buffers"].empty()) return "no buffers";
            doc["buffers"][0]["uri"] = uris[rng() % uris.size()];
            return "buffer uri " + doc["buffers"][0]["uri"].dump();
        }
        case 4: {  // primitive attributes and indices
            json& prim = doc["meshes"][0]["primitives"][0];
            static const std::vector<std::string> slots{"indices", "mode", "material"};
            const std::string slot = slots[rng() % slots.size()];
            if (rng() % 2) prim[slot] = oddInteger(rng);
            else prim["attributes"][(rng() % 2) ? "POSITION" : "NORMAL"] = oddInteger(rng);
            return "primitive " + prim.dump();
        }
        default: {  // node graph: cycles, repeats, references past the end
            json& nodes = doc["nodes"];
            const size_t n = rng() % (nodes.size() + 2);
            nodes[rng() % nodes.size()]["children"] = {n, n, 0};
            return "children " + std::to_string(n);
        }
    }
}

// The byte range of the image's data URI in `text` (left intact by byte mutations).
std::pair<size_t, size_t> imageRange(const std::string& text) {
    const size_t start = text.find("data:image/png");
    return {start, start == std::string::npos ? start : text.find('"', start)};
}

std::string mutateBytes(std::string& bytes, size_t protectFrom, size_t protectTo, std::mt19937& rng) {
    auto position = [&] {
        for (;;) {
            const size_t p = rng() % std::max<size_t>(bytes.size(), 1);
            if (p < protectFrom || p >= protectTo) return p;
        }
    };
    static const std::string specials = "{}[]\",:0-9e.\\";
    const size_t p = position();
    switch (rng() % 4) {
        case 0: bytes[p] = char(rng()); return "byte " + std::to_string(p);
        case 1: bytes[p] = specials[rng() % specials.size()]; return "special at " + std::to_string(p);
        case 2: bytes.insert(p, std::string(1 + rng() % 64, specials[rng() % 4])); return "brackets at " + std::to_string(p);
        default:
            if (p >= protectFrom && protectFrom != std::string::npos) return "cut skipped";
            bytes.resize(p);
            return "cut at " + std::to_string(p);
    }
}

}  // namespace

TEST(GltfFuzz, StructuralMutantsEndInSceneErrorOrAValidScene) {
    TempDir dir;
    fs::create_directories(dir.path / "subdir");
    const std::vector<uint8_t> bin = testBin();
    writeFile(dir.file("test.bin"), bin.data(), bin.size());
    std::mt19937 rng(20261123);
    Outcome out;
    for (int i = 0; i < kStructuralMutants; ++i) {
        const int form = i % 3;  // data URI, .bin file, GLB
        json doc = testGltf(form == 0 ? dataUri(bin) : form == 1 ? "test.bin" : "", bin.size());
        std::string mutation;
        for (int k = 0, edits = 1 + int(rng() % 3); k < edits; ++k) {
            try {
                mutation += mutateJson(doc, rng) + "; ";
            } catch (const json::exception&) {
                mutation += "(an edit that an earlier one made inapplicable); ";  // e.g. a field now an array
            }
        }
        std::string path;
        if (form == 2) {
            const std::vector<uint8_t> glb = glbBytes(doc, bin);
            path = dir.file("mutant.glb");
            writeFile(path, glb.data(), glb.size());
        } else {
            path = writeGltf(dir, "mutant.gltf", doc);
        }
        SCOPED_TRACE("mutant " + std::to_string(i));
        loadMutant(path, mutation, out);
        if (HasFatalFailure()) return;
    }
    EXPECT_EQ(out.loaded + out.refused, kStructuralMutants);
    EXPECT_GT(out.refused, kStructuralMutants / 4);  // the mutations do reach the checks
    EXPECT_GT(out.loaded, 10);                         // and some stay valid
    std::printf("structural mutants: %d loaded, %d refused\n", out.loaded, out.refused);
}

TEST(GltfFuzz, ByteMutantsEndInSceneErrorOrAValidScene) {
    TempDir dir;
    const std::vector<uint8_t> bin = testBin();
    const std::string text = testGltf(dataUri(bin), bin.size()).dump(1);
    const auto [imageFrom, imageTo] = imageRange(text);
    ASSERT_NE(imageFrom, std::string::npos);
    std::vector<uint8_t> glb = glbBytes(testGltf("", bin.size()), bin);
    const std::string glbText(glb.begin(), glb.end());
    const auto [glbImageFrom, glbImageTo] = imageRange(glbText);
    std::mt19937 rng(7);
    Outcome out;
    for (int i = 0; i < kByteMutants; ++i) {
        const bool asGlb = i % 2;
        std::string bytes = asGlb ? glbText : text;
        std::string mutation;
        for (int k = 0, edits = 1 + int(rng() % 4); k < edits; ++k) {
            if (asGlb && rng() % 3 == 0) {  // header and chunk fields: version, lengths, chunk types
                const size_t field = std::vector<size_t>{4, 8, 12, 16}[rng() % 4];
                const uint32_t v = std::vector<uint32_t>{0, 1, 3, 19, 20, uint32_t(bytes.size()), 0xFFFFFFFFu,
                                                         uint32_t(rng())}[rng() % 8];
                std::memcpy(&bytes[field], &v, 4);
                mutation += "header " + std::to_string(field) + " = " + std::to_string(v) + "; ";
            } else {
                mutation += mutateBytes(bytes, asGlb ? glbImageFrom : imageFrom, asGlb ? glbImageTo : imageTo, rng) + "; ";
            }
        }
        const std::string path = dir.file(asGlb ? "mutant.glb" : "mutant.gltf");
        writeFile(path, bytes);
        SCOPED_TRACE("mutant " + std::to_string(i));
        loadMutant(path, mutation, out);
        if (HasFatalFailure()) return;
    }
    EXPECT_EQ(out.loaded + out.refused, kByteMutants);
    EXPECT_GT(out.refused, kByteMutants / 2);
    std::printf("byte mutants: %d loaded, %d refused\n", out.loaded, out.refused);
}
