// KHR_texture_transform and TEXCOORD_1: the loader's uvs against the specification's example, and the
// rasterizer's G-buffer and the path tracer against texels picked by hand from a 16x16 texture of
// 4x4-texel blocks, each block its own colour.
#include <cmath>

#include <gtest/gtest.h>

#include "cli_run.h"
#include "gltf_test_util.h"
#include "io/image_io.h"
#include "scene/gltf_texture_transform.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

// Block (column c, row r) of the texture: sRGB bytes (40 + 60c, 40 + 60r, 200).
uint8_t blockRed(int c) { return uint8_t(40 + 60 * c); }
uint8_t blockGreen(int r) { return uint8_t(40 + 60 * r); }

std::vector<uint8_t> blockPng() {
    std::vector<uint8_t> px(16 * 16 * 3);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            uint8_t* p = &px[size_t(y * 16 + x) * 3];
            p[0] = blockRed(x / 4), p[1] = blockGreen(y / 4), p[2] = 200;
        }
    std::vector<uint8_t> png;
    stbi_write_png_to_func(
        [](void* ctx, void* data, int size) {
            auto* out = static_cast<std::vector<uint8_t>*>(ctx);
            out->insert(out->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
        },
        &png, 16, 16, 3, px.data(), 48);
    return png;
}

float srgbToLinear(uint8_t b) {
    const float c = b / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// A quad x, y in [-1, 1] at z = 0 facing +z. TEXCOORD_0 is junk (all 0.9); TEXCOORD_1 maps the quad's
// top-left corner to (0, 0) and its bottom-right to (1, 1), as the image's rows run.
json quadDoc(const std::vector<uint8_t>& bin, const json& textureInfo) {
    return json{
        {"asset", {{"version", "2.0"}}},
        {"extensionsUsed", {"KHR_texture_transform"}},
        {"extensionsRequired", {"KHR_texture_transform"}},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}, {"TEXCOORD_1", 2}}},
                                      {"indices", 3}, {"material", 0}}}}}}},
        {"materials", {{{"pbrMetallicRoughness", {{"baseColorTexture", textureInfo}}}}}},
        {"textures", {{{"source", 0}}}},
        {"images", {{{"uri", "data:image/png;base64," + base64(blockPng())}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}, {"min", {-1, -1, 0}}, {"max", {1, 1, 0}}},
          {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
          {{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
          {{"bufferView", 3}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
          {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 32}},
          {{"buffer", 0}, {"byteOffset", 80}, {"byteLength", 32}},
          {{"buffer", 0}, {"byteOffset", 112}, {"byteLength", 12}}}},
        {"buffers", {{{"byteLength", bin.size()}, {"uri", dataUri(bin)}}}},
    };
}

std::vector<uint8_t> quadBin() {
    std::vector<uint8_t> bin;
    for (float f : {-1.f, 1.f, 0.f, 1.f, 1.f, 0.f, -1.f, -1.f, 0.f, 1.f, -1.f, 0.f}) append(bin, f);
    for (int i = 0; i < 8; ++i) append(bin, 0.9f);
    for (float f : {0.f, 0.f, 1.f, 0.f, 0.f, 1.f, 1.f, 1.f}) append(bin, f);
    for (uint16_t i : {0, 2, 1, 1, 2, 3}) append(bin, uint16_t(i));
    return bin;
}

// The specification's example: offset (0, 1), rotation pi/2, scale 0.5 on TEXCOORD_1.
json specExample() {
    return {{"index", 0}, {"texCoord", 0},
            {"extensions", {{"KHR_texture_transform",
                             {{"offset", {0, 1}}, {"rotation", 1.57079632679}, {"scale", {0.5, 0.5}}, {"texCoord", 1}}}}}};
}

}  // namespace

// u' = 0.5 v, v' = 1 - 0.5 u: the unit square lands on the image's lower-left quadrant (the example's
// own words), and the quad's corners on these points.
TEST(TextureTransform, LoaderAppliesTheSpecificationsExample) {
    const glm::mat3x2 m = gltf::textureTransformMatrix({0, 1}, 1.57079632679f, {0.5f, 0.5f});
    EXPECT_NEAR(glm::distance(m * glm::vec3(1, 0, 1), glm::vec2(0.0f, 0.5f)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(m * glm::vec3(0, 1, 1), glm::vec2(0.5f, 1.0f)), 0.0f, 1e-6f);
    TempDir dir;
    const Scene s = loadGltf(writeGltf(dir, "quad.gltf", quadDoc(quadBin(), specExample())));
    EXPECT_TRUE(s.warnings.empty()) << ::testing::PrintToString(s.warnings);
    ASSERT_EQ(s.vertices.size(), 4u);
    const glm::vec2 expected[4] = {{0.0f, 1.0f}, {0.0f, 0.5f}, {0.5f, 1.0f}, {0.5f, 0.5f}};  // TEXCOORD_1 corners
    for (size_t i = 0; i < 4; ++i)
        EXPECT_NEAR(glm::distance(s.vertices[i].uv, expected[i]), 0.0f, 1e-6f) << i;
}

TEST(TextureTransform, BadValuesAreRefusedAndAMissingSetWarns) {
    TempDir dir;
    json bad = specExample();
    bad["extensions"]["KHR_texture_transform"]["rotation"] = 1e300;
    EXPECT_NE(sceneError([&] { loadGltf(writeGltf(dir, "bad.gltf", quadDoc(quadBin(), bad))); }).find("rotation"),
              std::string::npos);
    json set3 = specExample();
    set3["extensions"]["KHR_texture_transform"]["texCoord"] = 3;
    const Scene s = loadGltf(writeGltf(dir, "set3.gltf", quadDoc(quadBin(), set3)));
    ASSERT_EQ(s.warnings.size(), 1u) << ::testing::PrintToString(s.warnings);
    EXPECT_NE(s.warnings[0].find("TEXCOORD_3"), std::string::npos) << s.warnings[0];
    for (const Vertex& v : s.vertices) EXPECT_EQ(v.uv, glm::vec2(0.0f));
}

// The quad seen head-on fills a 64x64 image (--camera at z = 2, fovy 45 degrees: the view's half
// height is 2 tan(22.5) = 0.828 of the quad's 1). Pixel (x, y) sees TEXCOORD_1 = 0.5 + (s - 0.5) 0.828
// with s = (x + 0.5) / 64, and the transformed u' = 0.5 v, v' = 1 - 0.5 u. At the four pixels below
// that is (by hand) u' 0.150 or 0.357, v' 0.850 or 0.643: blocks (0, 3), (0, 2), (1, 3), (1, 2),
// at least 0.1 (1.6 texels) inside each block, so bilinear filtering of level 0 returns the block's
// colour. Without the transform the blocks would be (1, 1), (2, 1), (1, 2), (2, 2).
TEST(TextureTransform, RasterizerAndPathTracerShowTheHandPickedTexels) {
    ScratchDir dir("texture_transform");
    TempDir files;
    const std::string scene = writeGltf(files, "quad.gltf", quadDoc(quadBin(), specExample()));
    const std::string view = " --width 64 --height 64 --camera 0,0,2,0,0,0,0,1,0,45 "
                             "--light directional,0,0,-1,3.14159265,1,1,1";
    // E = pi facing the light: the direct radiance of a Lambertian surface is its albedo.
    const Cli raster = runCli(dir, "render " + scene + view + " --gi none --aov albedo -o " + dir.file("raster.exr"));
    ASSERT_EQ(raster.status, 0) << raster.err;
    const Cli traced = runCli(dir, "reference " + scene + view + " --spp 1 --bounces 0 --aov direct --sky none -q -o " +
                                       dir.file("traced.exr"));
    ASSERT_EQ(traced.status, 0) << traced.err;
    struct Probe {
        uint32_t x, y;
        int column, row;
    };
    const Probe probes[] = {{16, 16, 0, 3}, {48, 16, 0, 2}, {16, 48, 1, 3}, {48, 48, 1, 2}};
    for (const char* name : {"raster.exr", "traced.exr"}) {
        const ImageF img = readExr(dir.file(name));
        ASSERT_EQ(img.width, 64u);
        for (const Probe& p : probes) {
            const float* px = &img.rgba[(size_t(p.y) * 64 + p.x) * 4];
            EXPECT_NEAR(px[0], srgbToLinear(blockRed(p.column)), 0.01f) << name << " at " << p.x << "," << p.y;
            EXPECT_NEAR(px[1], srgbToLinear(blockGreen(p.row)), 0.01f) << name << " at " << p.x << "," << p.y;
            EXPECT_NEAR(px[2], srgbToLinear(200), 0.01f) << name << " at " << p.x << "," << p.y;
        }
    }
}
