// Bad inputs that crashed, ran unbounded or passed silently, one test per class: each now ends in one
// error line and a non-zero exit, one warning, or a correct result. (The glTF container and ranges:
// glb_fuzz_test.cpp; texture transforms: texture_transform_test.cpp.)
#include <cmath>
#include <regex>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_run.h"
#include "gltf_test_util.h"
#include "io/file_write.h"
#include "io/image_io.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

json goodDoc() {
    const std::vector<uint8_t> bin = testBin();
    return testGltf(dataUri(bin), bin.size());
}

bool hasWarning(const Scene& s, const std::string& word) {
    for (const std::string& w : s.warnings)
        if (w.find(word) != std::string::npos) return true;
    return false;
}

std::string warnings(const Scene& s) { return ::testing::PrintToString(s.warnings); }

}  // namespace

// One measured frame leaves no wall-clock interval: the statistics of an empty series are "-" in the
// table and null in the JSON (the empty series was indexed at size - 1: a segfault).
TEST(BadInput, BenchStatisticsHoldForOneFrame) {
    ScratchDir dir("bench_one");
    const Cli r = runCli(dir, "bench cornell --frames 1 --warmup 0 --width 32 --height 24 --json " + dir.file("b.json"));
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(readText(dir.file("b.json")));
    EXPECT_EQ(j["frames"], 1);
    EXPECT_TRUE(j["wall_ms"]["median"].is_null());
    EXPECT_TRUE(j["frame_ms"]["median"].is_number());
    EXPECT_NE(r.out.find("wall clock per frame"), std::string::npos) << r.out;
}

// Every writer goes through writeFileChecked: a full disk is an error naming the file, whatever the
// format (stb's PNG writer and tinyexr's fclose went unchecked: success on /dev/full).
TEST(BadInput, WritesToAFullDiskFailNamingTheFile) {
    const auto message = [](const std::function<void()>& write) {
        try {
            write();
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string("nothing thrown");
    };
    const std::vector<uint8_t> rgba8(4 * 4 * 4, 128);
    const std::vector<float> rgba32f(4 * 4 * 4, 0.5f);
    for (const std::string& msg : {message([] { writeTextFile("/dev/full", "{}"); }),
                                   message([&] { writePng("/dev/full", 4, 4, rgba8); }),
                                   message([&] { writeExr("/dev/full", 4, 4, rgba32f); })}) {
        EXPECT_NE(msg.find("cannot write /dev/full"), std::string::npos) << msg;
        EXPECT_NE(msg.find("No space left"), std::string::npos) << msg;
    }
    ScratchDir dir("full_disk");
    for (const char* name : {"full.png", "full.exr", "full.json"})
        std::filesystem::create_symlink("/dev/full", dir.path / name);
    const std::string small = " --width 32 --height 24";
    expectRefused(dir, "render cornell" + small + " -o " + dir.file("full.png"), "full.png");
    expectRefused(dir, "render cornell" + small + " -o " + dir.file("full.exr"), "full.exr");
    expectRefused(dir, "bench cornell --frames 2 --warmup 0" + small + " --json " + dir.file("full.json"), "full.json");
    expectRefused(dir, "stability cornell --frames 3 --no-reference" + small + " --json " + dir.file("full.json"),
                  "full.json");
}

// Intensity x colour above 65504 (RGBA16F's largest value) is refused before any work; the message's
// suggestion renders a finite, lit image.
TEST(BadInput, LightThatOverflowsTheLightingIsRefusedWithAWorkingSuggestion) {
    ScratchDir dir("light_overflow");
    const Cli r = runCli(dir, "render cornell --width 32 --height 24 --light directional,0,-1,0,1e9,3,3,3 -o " +
                                  dir.file("x.exr"));
    expectOneErrorLine(r, "1e9", "65504");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.err, m, std::regex("largest intensity with this colour is ([0-9.e+]+)"))) << r.err;
    const std::string suggested = m[1];
    EXPECT_LE(std::stod(suggested) * 3.0, 65504.0);
    const Cli ok = runCli(dir, "render cornell --width 32 --height 24 --light directional,0,-1,0," + suggested +
                                   ",3,3,3 -o " + dir.file("ok.exr"));
    ASSERT_EQ(ok.status, 0) << ok.err;
    const ImageF img = readExr(dir.file("ok.exr"));
    double sum = 0.0;
    for (float v : img.rgba) {
        ASSERT_TRUE(std::isfinite(v));
        sum += v;
    }
    EXPECT_GT(sum, 0.0);
    expectRefused(dir, "render cornell --light point,0,1,0,1e9 -o " + dir.file("p.exr"), "65504");
}

// As --camera refuses one such view, --camera-keys refuses a path that has one at any time: at a key,
// or between keys (the eye passing through the target, the view swinging through the up vector).
TEST(BadInput, DegenerateCameraKeysAreRefused) {
    ScratchDir dir("camera_keys");
    const std::string render = "render cornell --width 32 --height 24 -o " + dir.file("x.png") + " --camera-keys ";
    expectRefused(dir, render + "'0,0,1,3,0,1,3;1,0,1,4,0,1,0'", "eye and target coincide");
    expectRefused(dir, render + "'0,0,5,0,0,0,0'", "parallel to the up vector");
    expectRefused(dir, render + "'0,0,1,2,0,1,0;1,0,1,-2,0,1,0'", "t = 0.5");
    expectRefused(dir, render + "'0,0,2,-1,0,1,0;2,0,2,1,0,1,0'", "t = 1 s the view direction (target - eye) is parallel");
}

// glTF values the specification forbids or that would overflow the lighting: one warning each, and
// a value that renders.
TEST(BadInput, GltfLightAndCameraValuesAreClampedWithAWarning) {
    TempDir dir;
    json doc = goodDoc();
    auto& lights = doc["extensions"]["KHR_lights_punctual"]["lights"];
    lights[0]["spot"]["outerConeAngle"] = 0;
    lights[0]["intensity"] = 3e38;
    lights.push_back({{"type", "spot"}, {"spot", {{"outerConeAngle", 2.0}}}});
    lights.push_back({{"type", "area"}});
    doc["nodes"].push_back({{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
    doc["nodes"].push_back({{"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}});
    doc["scenes"][0]["nodes"] = {0, 2, 3, 4, 5};
    doc["cameras"][0]["perspective"]["znear"] = 200;  // above zfar 100
    doc["cameras"][0]["perspective"]["yfov"] = 0;
    const Scene s = loadGltf(writeGltf(dir, "lights.gltf", doc));
    ASSERT_EQ(s.lights.size(), 2u) << warnings(s);  // the unknown type is dropped
    EXPECT_NEAR(s.lights[0].outerConeAngle, 0.7853982f, 1e-6f);
    EXPECT_LE(s.lights[0].intensity * 1.0f, 65504.0f);
    EXPECT_NEAR(s.lights[1].outerConeAngle, 1.5707964f, 1e-6f);
    for (const char* word : {"outer angle 0", "intensity 3e+38", "outer angle 2", "unknown type 'area'",
                             "yfov 0", "zfar 100"})
        EXPECT_TRUE(hasWarning(s, word)) << word << ": " << warnings(s);
    ASSERT_EQ(s.cameras.size(), 1u);
    EXPECT_GT(s.cameras[0].fovy, 0.0f);
    EXPECT_EQ(s.cameras[0].zfar, 0.0f);  // from the bounds
    doc["cameras"][0]["perspective"]["yfov"] = 4;
    EXPECT_TRUE(hasWarning(loadGltf(writeGltf(dir, "fov.gltf", doc)), "yfov 4"));
}

TEST(BadInput, GltfVersionAndDanglingChannelWarn) {
    TempDir dir;
    json doc = goodDoc();
    doc["asset"]["version"] = "3.0";
    doc["animations"] = {{{"channels", {{{"sampler", 0}, {"target", {{"node", 99}, {"path", "translation"}}}}}},
                          {"samplers", {{{"input", 0}, {"output", 0}}}}}};
    const Scene s = loadGltf(writeGltf(dir, "version.gltf", doc));
    EXPECT_TRUE(hasWarning(s, "asset.version '3.0'")) << warnings(s);
    EXPECT_TRUE(hasWarning(s, "target node 99 does not exist")) << warnings(s);
}

// NaN or infinite positions (binary floats: JSON has none) and world transforms that overflow are
// refused with the vertex or node named; the printed bounds held inf.
TEST(BadInput, GltfNonFinitePositionsAreRefused) {
    TempDir dir;
    for (const float bad : {std::nanf(""), INFINITY, 3e38f}) {
        std::vector<uint8_t> bin = testBin();
        std::memcpy(&bin[12], &bad, 4);  // vertex 1's x (3e38: finite in the file, beyond float once scaled by 2)
        const std::string msg = sceneError([&] { loadGltf(writeGltf(dir, "nan.gltf", testGltf(dataUri(bin), bin.size()))); });
        EXPECT_NE(msg.find("vertex 1"), std::string::npos) << bad << ": " << msg;
    }
    json doc = goodDoc();
    doc["nodes"][0]["scale"] = {1e30, 1, 1};
    doc["nodes"][1]["scale"] = {1e30, 1, 1};  // the child's world scale is 1e60
    const std::string msg = sceneError([&] { loadGltf(writeGltf(dir, "scale.gltf", doc)); });
    EXPECT_NE(msg.find("node 1: its world transform is not finite"), std::string::npos) << msg;
}

// eval measures relative errors against the reference's noise: one path per pixel estimates no noise
// and a few pixels leave nothing to measure. Refused with sizes that work.
TEST(BadInput, EvalSizesItCannotMeasureAreRefused) {
    ScratchDir dir("eval_size");
    expectRefused(dir, "eval cornell --width 1 --height 1 --spp 1", "--spp 1");
    expectRefused(dir, "eval cornell --width 1 --height 1 --spp 4", "--width");
}

// The reference cache's images must have the size its key names: one of another size is an error
// naming the file (it said "image sizes differ: 32x24 and 32x64").
TEST(BadInput, EvalCacheImageOfAnotherSizeIsNamed) {
    ScratchDir dir("eval_cache");
    const std::string cache = dir.file("cache"), json = cache + "/reference.json";
    const std::string args = "eval cornell --width 16 --height 16 --spp 2 -q --reference " + cache;
    // Only the reference is needed: the run is stopped once its cache is written (reference.json last).
    const int rc = std::system(fmt::format("({} {} >/dev/null 2>&1 & pid=$!; for i in $(seq 1200); do [ -s {} ] && "
                                           "break; sleep 0.1; done; sleep 0.5; kill $pid; wait $pid) 2>/dev/null",
                                           PENUMBRA_BIN, args, json).c_str());
    (void)rc;  // the run is killed: its status says nothing
    ASSERT_TRUE(std::filesystem::exists(json));
    writeExr(cache + "/mask.exr", 16, 32, std::vector<float>(16 * 32 * 4, 1.0f));
    const Cli r = runCli(dir, args);
    expectOneErrorLine(r, "cache", cache + "/mask.exr");
    EXPECT_NE(r.err.find("16x32, expected 16x16"), std::string::npos) << r.err;
}

// The strongest light --light takes over a 2 km ground: an RSM texel covers about 16 m^2, and its
// flux, 65504 x 0.8 x 16, is more than a half float holds. It is clamped at 65504 in the RSM (it was
// stored as infinity: NaN indirect light, a black image with RSM, no indirect light with LPV).
TEST(BadInput, StrongestLightOverALargeSceneStaysFinite) {
    TempDir files;
    std::vector<uint8_t> bin;
    for (float f : {-1000.f, 0.f, -1000.f, 1000.f, 0.f, -1000.f, -1000.f, 0.f, 1000.f, 1000.f, 0.f, 1000.f,
                    -100.f, 0.f, 0.f, 100.f, 0.f, 0.f, -100.f, 200.f, 0.f, 100.f, 200.f, 0.f})
        append(bin, f);
    for (uint16_t i : {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6}) append(bin, uint16_t(i));
    const json doc{
        {"asset", {{"version", "2.0"}}},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"material", 0}}}}}}},
        {"materials", {{{"doubleSided", true}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1}}}}}}},
        {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 8}, {"type", "VEC3"},
                        {"min", {-1000, 0, -1000}}, {"max", {1000, 200, 1000}}},
                       {{"bufferView", 1}, {"componentType", 5123}, {"count", 12}, {"type", "SCALAR"}}}},
        {"bufferViews", {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 96}},
                         {{"buffer", 0}, {"byteOffset", 96}, {"byteLength", 24}}}},
        {"buffers", {{{"byteLength", bin.size()}, {"uri", dataUri(bin)}}}}};
    const std::string scene = writeGltf(files, "ground.gltf", doc);
    ScratchDir dir("large_scene");
    for (const char* gi : {"rsm", "lpv"}) {
        const std::string out = dir.file(std::string(gi) + ".exr");
        const Cli r = runCli(dir, "render " + scene + " --width 16 --height 16 --gi " + gi + " --aov indirect "
                                  "--camera 0,300,800,0,50,0,0,1,0,45 --light directional,-0.3,-1,-0.5,65504,1,1,1 -o " + out);
        ASSERT_EQ(r.status, 0) << r.err;
        const ImageF img = readExr(out);
        double sum = 0.0;
        for (float v : img.rgba) {
            ASSERT_TRUE(std::isfinite(v)) << gi;
            sum += v;
        }
        EXPECT_GT(sum, 0.0) << gi;  // the ground lights the wall
    }
}
