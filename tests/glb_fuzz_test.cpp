// In-process mutation fuzzer of the GLB container and of the byte ranges the loader reads (fixed
// seeds): the test file (gltf_test_util.h) as a GLB whose PNG lies in a bufferView of the BIN chunk,
// as exporters write it, with one accessor made sparse. Mutations move and resize the image's and the
// accessors' bufferViews and the sparse ranges to the edges of the buffer and past them (offsets
// 4096, 65536, 2^31 - 1), resize the chunks and the header's length, cut the file, and rewrite the
// PNG's header (sizes up to 2^31 - 1 texels a side). Every mutant must load within 10 s and end in
// SceneError with a one-line message, or in a scene that satisfies the loader's invariants; the first
// three that load are rendered at 64x64 by the CLI, each within 10 s.
#include <chrono>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "cli_run.h"
#include "gltf_test_util.h"
#include "scene/scene.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

constexpr int kMutants = 700;

// The BIN chunk: the test mesh, then the PNG at a 4-byte boundary.
struct GlbParts {
    json doc;
    std::vector<uint8_t> bin;
    size_t pngOffset = 0, pngSize = 0;
};

GlbParts embeddedImageGlb() {
    GlbParts p;
    p.bin = testBin();
    while (p.bin.size() % 4) p.bin.push_back(0);
    const std::vector<uint8_t> png = testPng();
    p.pngOffset = p.bin.size();
    p.pngSize = png.size();
    p.bin.insert(p.bin.end(), png.begin(), png.end());
    p.doc = testGltf("", p.bin.size());
    p.doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", p.pngOffset}, {"byteLength", p.pngSize}});
    p.doc["images"] = {{{"bufferView", 3}, {"mimeType", "image/png"}}};
    // The uvs' accessor made sparse: its third element replaced from the index bufferView's bytes.
    p.doc["accessors"][2]["sparse"] = {{"count", 1},
                                       {"indices", {{"bufferView", 1}, {"byteOffset", 0}, {"componentType", 5123}}},
                                       {"values", {{"bufferView", 2}, {"byteOffset", 0}}}};
    return p;
}

json edgeValue(std::mt19937& rng, size_t binSize) {
    const std::vector<json> values{0, 1, 3, 4, 36, 4096, 65536, 2147483647, 2147483648ull, -1,
                                   binSize - 1, binSize, binSize + 1, binSize * 2};
    return values[rng() % values.size()];
}

// One edit of the ranges: a bufferView (the image's most often), an accessor or the sparse part.
std::string mutateRanges(json& doc, std::mt19937& rng, size_t binSize) {
    json& views = doc["bufferViews"];
    switch (rng() % 4) {
        case 0:
        case 1: {
            const size_t v = rng() % 2 ? 3 : rng() % views.size();
            const std::string key = rng() % 2 ? "byteOffset" : "byteLength";
            views[v][key] = edgeValue(rng, binSize);
            return "bufferView " + std::to_string(v) + "." + key + " = " + views[v][key].dump();
        }
        case 2: {
            json& a = doc["accessors"][rng() % doc["accessors"].size()];
            static const std::vector<std::string> keys{"byteOffset", "count", "bufferView"};
            const std::string key = keys[rng() % keys.size()];
            a[key] = key == "bufferView" ? json(rng() % (views.size() + 1)) : edgeValue(rng, binSize);
            return "accessor." + key + " = " + a[key].dump();
        }
        default: {
            json& sparse = doc["accessors"][2]["sparse"];
            static const std::vector<std::string> parts{"indices", "values"};
            const std::string part = parts[rng() % 2];
            if (rng() % 3 == 0) {
                sparse["count"] = edgeValue(rng, binSize);
                return "sparse.count = " + sparse["count"].dump();
            }
            sparse[part]["byteOffset"] = edgeValue(rng, binSize);
            return "sparse." + part + ".byteOffset = " + sparse[part]["byteOffset"].dump();
        }
    }
}

void put32(std::vector<uint8_t>& bytes, size_t at, uint32_t v) {
    if (at + 4 <= bytes.size()) std::memcpy(&bytes[at], &v, 4);
}

// One edit of the container or of the PNG's header inside the BIN chunk (big-endian IHDR sizes at
// bytes 16 and 20 of the PNG).
std::string mutateContainer(std::vector<uint8_t>& glb, size_t pngAt, std::mt19937& rng) {
    const uint32_t jsonLength = uint32_t(glb[12]) | uint32_t(glb[13]) << 8 | uint32_t(glb[14]) << 16 |
                                uint32_t(glb[15]) << 24;
    const size_t binHeader = 20 + jsonLength;
    const std::vector<uint32_t> values{0, 1, 8, 12, 20, uint32_t(glb.size()), uint32_t(glb.size() + 4),
                                       0x7FFFFFFFu, 0xFFFFFFFFu};
    const uint32_t v = values[rng() % values.size()];
    switch (rng() % 5) {
        case 0: put32(glb, 8, v); return "total length = " + std::to_string(v);
        case 1: put32(glb, binHeader, v); return "BIN length = " + std::to_string(v);
        case 2: put32(glb, binHeader + 4, rng() % 2 ? 0x4E4F534Au : uint32_t(rng())); return "BIN chunk type";
        case 3: {
            const size_t cut = binHeader + rng() % (glb.size() - binHeader);
            glb.resize(cut);
            return "cut at " + std::to_string(cut);
        }
        default: {
            const size_t at = pngAt + 16 + (rng() % 2) * 4;
            const uint32_t size = std::vector<uint32_t>{0, 8193, 16000, 16385, 100000, 0x7FFFFFFFu}[rng() % 6];
            if (at + 4 <= glb.size())
                for (int k = 0; k < 4; ++k) glb[at + size_t(k)] = uint8_t(size >> (24 - 8 * k));
            return "PNG size field = " + std::to_string(size);
        }
    }
}

}  // namespace

TEST(GlbFuzz, ContainerAndRangeMutantsEndInSceneErrorOrAValidScene) {
    TempDir dir;
    const GlbParts base = embeddedImageGlb();
    {  // the unmutated file loads with its texture
        const std::vector<uint8_t> glb = glbBytes(base.doc, base.bin);
        writeFile(dir.file("base.glb"), glb.data(), glb.size());
        const Scene s = loadGltf(dir.file("base.glb"));
        ASSERT_EQ(s.textures.size(), 1u) << ::testing::PrintToString(s.warnings);
        EXPECT_EQ(s.textures[0].width, 2u);
    }
    std::mt19937 rng(20261127);
    int loaded = 0, refused = 0;
    double slowest = 0.0;
    constexpr size_t kRendered = 3;
    std::vector<std::string> rendered;
    for (int i = 0; i < kMutants; ++i) {
        json doc = base.doc;
        std::string mutation;
        const bool ranges = i % 2 == 0;
        if (ranges)
            for (int k = 0, edits = 1 + int(rng() % 2); k < edits; ++k) mutation += mutateRanges(doc, rng, base.bin.size()) + "; ";
        std::vector<uint8_t> glb = glbBytes(doc, base.bin);
        const size_t jsonLength = glb[12] | size_t(glb[13]) << 8;
        if (!ranges) mutation += mutateContainer(glb, 20 + jsonLength + 8 + base.pngOffset, rng);
        const std::string path = dir.file("mutant.glb");
        writeFile(path, glb.data(), glb.size());
        SCOPED_TRACE("mutant " + std::to_string(i) + ": " + mutation);
        const auto start = std::chrono::steady_clock::now();
        try {
            const Scene s = loadGltf(path);
            ++loaded;
            for (uint32_t index : s.indices) ASSERT_LT(index, s.vertices.size());
            for (const Material& m : s.materials) ASSERT_LT(m.baseColorTexture, int32_t(s.textures.size()));
            for (const Texture& t : s.textures) ASSERT_EQ(t.rgba8.size(), size_t(t.width) * t.height * 4);
            for (const Vertex& v : s.vertices) ASSERT_TRUE(std::isfinite(v.position.x + v.position.y + v.position.z));
            if (rendered.size() < kRendered) {
                rendered.push_back(dir.file("loaded" + std::to_string(rendered.size()) + ".glb"));
                std::filesystem::copy_file(path, rendered.back());
            }
        } catch (const SceneError& e) {
            ++refused;
            const std::string msg = e.what();
            EXPECT_FALSE(msg.empty());
            EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
            EXPECT_NE(msg.find(path), std::string::npos) << msg;
        } catch (const std::exception& e) {
            ADD_FAILURE() << "not a SceneError: " << e.what();
        }
        slowest = std::max(slowest, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        if (HasFatalFailure()) return;
    }
    // A few of the mutants that load, rendered as a user would: each in well under 10 s at 64x64.
    ScratchDir scratch("glb_fuzz");
    for (const std::string& file : rendered) {
        const auto renderStart = std::chrono::steady_clock::now();
        const Cli r = runCli(scratch, "render " + file + " --width 64 --height 64 -o " + scratch.file("m.png"));
        EXPECT_EQ(r.status, 0) << file << ": " << r.err;
        slowest = std::max(slowest, std::chrono::duration<double>(std::chrono::steady_clock::now() - renderStart).count());
    }
    EXPECT_LT(slowest, 10.0);
    EXPECT_EQ(loaded + refused, kMutants);
    EXPECT_GT(refused, kMutants / 4);  // the mutations reach the checks
    EXPECT_GT(loaded, 10);             // and some stay valid
    std::printf("GLB mutants: %d loaded, %d refused, slowest %.3f s\n", loaded, refused, slowest);
}

// The audit's three: an image bufferView at byte 2^31 - 1 (crashed while copying), 4096 and 65536
// (read past the buffer, then "unknown image type").
TEST(GlbFuzz, ImageBufferViewPastItsBufferIsRefused) {
    TempDir dir;
    for (const uint64_t offset : {2147483647ull, 4096ull, 65536ull}) {
        GlbParts p = embeddedImageGlb();
        p.doc["bufferViews"][3]["byteOffset"] = offset;
        const std::vector<uint8_t> glb = glbBytes(p.doc, p.bin);
        const std::string path = dir.file("image_past.glb");
        writeFile(path, glb.data(), glb.size());
        const std::string msg = sceneError([&] { loadGltf(path); });
        EXPECT_NE(msg.find("exceeds its buffer"), std::string::npos) << offset << ": " << msg;
        EXPECT_NE(msg.find(path), std::string::npos) << msg;
    }
}

// A 2x1 PNG whose header claims 16000 x 16000 texels (a gigabyte decoded, which stb_image's own
// limit lets through) is dropped from its header alone, with one warning; the material renders
// untextured.
TEST(GlbFuzz, ImageLargerThanAnyUploadIsDroppedBeforeDecoding) {
    TempDir dir;
    GlbParts p = embeddedImageGlb();
    for (size_t at : {p.pngOffset + 16, p.pngOffset + 20})
        for (int k = 0; k < 4; ++k) p.bin[at + size_t(k)] = uint8_t(16000u >> (24 - 8 * k));
    const std::vector<uint8_t> glb = glbBytes(p.doc, p.bin);
    writeFile(dir.file("huge.glb"), glb.data(), glb.size());
    const auto start = std::chrono::steady_clock::now();
    const Scene s = loadGltf(dir.file("huge.glb"));
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
    EXPECT_TRUE(s.textures.empty());
    ASSERT_EQ(s.warnings.size(), 1u) << ::testing::PrintToString(s.warnings);
    EXPECT_NE(s.warnings[0].find("16000x16000"), std::string::npos) << s.warnings[0];
}
