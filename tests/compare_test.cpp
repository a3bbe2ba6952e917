// `penumbra compare` metrics on image pairs with known answers, the heat map, `penumbra eval`'s
// measurements on lavapipe (direct light of the rasterizer against the reference on cornell and VC;
// the GI rows), and bad input to the reference and compare commands (one error line, non-zero exit).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_run.h"
#include "eval/compare.h"
#include "eval/eval.h"
#include "gpu_fixture.h"
#include "reference/path_tracer.h"

using namespace penumbra;
using namespace penumbra::test;
namespace fs = std::filesystem;

namespace {

ImageF constant(uint32_t w, uint32_t h, const glm::vec3& c) {
    ImageF img{w, h, std::vector<float>(size_t(w) * h * 4, 1.0f)};
    for (size_t i = 0; i < size_t(w) * h; ++i)
        for (int k = 0; k < 3; ++k) img.rgba[i * 4 + k] = c[k];
    return img;
}

// A smooth test pattern with structure, values in [0.1, 1.1].
ImageF pattern(uint32_t w, uint32_t h) {
    ImageF img = constant(w, h, glm::vec3(0.0f));
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                img.rgba[(size_t(y) * w + x) * 4 + c] = 0.6f + 0.5f * std::sin(0.3f * x + 0.2f * y + float(c));
    return img;
}

}  // namespace

TEST(Compare, IdenticalImagesHaveNoErrorAndSsimOne) {
    const ImageF a = pattern(40, 30);
    const ImageMetrics m = compareImages(a, a);
    EXPECT_EQ(m.pixels, 1200u);
    EXPECT_EQ(m.rmse, 0.0);
    EXPECT_EQ(m.relL1, 0.0);
    EXPECT_EQ(m.maxError, 0.0);
    EXPECT_NEAR(m.ssim, 1.0, 1e-12);
}

TEST(Compare, MetricsOfKnownDifferences) {
    const ImageF b = pattern(40, 30);
    double sumB = 0.0, sumB2 = 0.0;
    for (size_t i = 0; i < b.rgba.size(); ++i)
        if (i % 4 != 3) sumB += b.rgba[i], sumB2 += double(b.rgba[i]) * b.rgba[i];
    ImageF a = b;  // A = B + 0.1 everywhere
    for (size_t i = 0; i < a.rgba.size(); ++i) a.rgba[i] += 0.1f;
    ImageMetrics m = compareImages(a, b);
    EXPECT_NEAR(m.rmse, 0.1, 1e-6);
    EXPECT_NEAR(m.meanBias, 0.1, 1e-6);
    EXPECT_NEAR(m.maxError, 0.1, 1e-6);
    EXPECT_NEAR(m.relL1, 0.1 * 3600 / sumB, 1e-6);
    EXPECT_NEAR(m.relL2, std::sqrt(0.01 * 3600 / sumB2), 1e-6);
    EXPECT_NEAR(m.refMean, sumB / 3600, 1e-6);
    a = b;  // A = 2 B: relative errors 1, bias = mean B
    for (size_t i = 0; i < a.rgba.size(); ++i) a.rgba[i] *= 2.0f;
    m = compareImages(a, b);
    EXPECT_NEAR(m.relL1, 1.0, 1e-6);
    EXPECT_NEAR(m.relL2, 1.0, 1e-6);
    EXPECT_NEAR(m.meanBias, sumB / 3600, 1e-6);
    // Against a black reference the relative errors are infinite, or 0 when A is black too.
    const ImageF black = constant(8, 8, glm::vec3(0.0f));
    EXPECT_TRUE(std::isinf(compareImages(constant(8, 8, glm::vec3(1.0f)), black).relL1));
    EXPECT_EQ(compareImages(black, black).relL2, 0.0);
}

TEST(Compare, SsimOfConstantImagesIsTheLuminanceTerm) {
    // No variance anywhere: SSIM = (2 a b + C1) / (a^2 + b^2 + C1), C1 = (0.01 L)^2, L = b here.
    const double a = 0.3, b = 0.5;
    const ImageMetrics m = compareImages(constant(20, 20, glm::vec3(float(a))), constant(20, 20, glm::vec3(float(b))));
    const double c1 = std::pow(0.01 * b, 2);
    EXPECT_NEAR(m.ssimRange, b, 1e-6);
    EXPECT_NEAR(m.ssim, (2 * a * b + c1) / (a * a + b * b + c1), 1e-6);
}

TEST(Compare, SsimFallsWithNoise) {
    const ImageF b = pattern(64, 64);
    std::mt19937 rng(7);
    double last = 1.0;
    for (float sigma : {0.01f, 0.05f, 0.2f}) {
        ImageF a = b;
        std::normal_distribution<float> n(0.0f, sigma);
        for (size_t i = 0; i < a.rgba.size(); ++i) a.rgba[i] += n(rng);
        const double s = compareImages(a, b).ssim;
        EXPECT_LT(s, last) << "noise " << sigma;
        last = s;
    }
    EXPECT_LT(last, 0.8);
}

TEST(Compare, MaskSelectsThePixelsCompared) {
    const ImageF b = pattern(16, 16);
    ImageF a = b;
    std::vector<uint8_t> mask(256, 1);
    for (int i = 0; i < 16; ++i) a.rgba[i * 4] += 5.0f, mask[i] = 0;  // first row differs, and is masked out
    const ImageMetrics m = compareImages(a, b, mask);
    EXPECT_EQ(m.pixels, 240u);
    EXPECT_EQ(m.maxError, 0.0);
    EXPECT_GT(compareImages(a, b).maxError, 4.9);
    EXPECT_THROW(compareImages(a, b, std::vector<uint8_t>(256, 0)), std::invalid_argument);
    EXPECT_THROW(compareImages(a, pattern(16, 8)), std::invalid_argument);
}

TEST(Compare, HeatMapRampAndScale) {
    const ImageF b = constant(4, 1, glm::vec3(0.0f));
    ImageF a = b;
    for (int x = 0; x < 4; ++x)
        for (int c = 0; c < 3; ++c) a.rgba[x * 4 + c] = float(x);  // luminance errors 0, 1, 2, 3
    double scale = 2.0;
    const std::vector<uint8_t> heat = errorHeatMap(a, b, {}, scale);
    EXPECT_EQ(heat[0], 0);  // 0: black
    EXPECT_EQ(heat[2], 4);
    EXPECT_EQ(heat[2 * 4], 252);  // >= scale: pale yellow
    EXPECT_EQ(heat[3 * 4 + 1], 255);
    EXPECT_GT(heat[1 * 4], heat[0]);
    double automatic = 0.0;
    errorHeatMap(a, b, {}, automatic);
    EXPECT_NEAR(automatic, 3.0, 1e-9) << "the 99th percentile of 4 errors is the largest";
}

// ---- the rasterizer against the reference (lavapipe) ----

namespace {

// Direct light of the rasterizer (hard shadows) against the reference's, over pixels with geometry.
ImageMetrics directAgreement(vk::Context& ctx, const Scene& scene, const Camera& cam, uint32_t w, uint32_t h) {
    ReferenceSettings rs;
    rs.width = w, rs.height = h, rs.spp = 1, rs.bounces = 0, rs.progress = false;
    const ReferenceImage ref = renderReference(scene, cam, rs);
    RenderSettings s;
    s.width = w, s.height = h, s.aov = Aov::Direct;
    Renderer r(ctx, scene, s);
    r.render(cam);
    const ImageF gpu{w, h, r.readHdr()};
    return compareImages(gpu, {w, h, ref.rgba(ReferenceAov::Direct)}, ref.covered);
}

class EvalTest : public GpuTest {};

}  // namespace

TEST_F(EvalTest, DirectLightAgreesWithReferenceOnCornell) {
    const Scene scene = makeBuiltinScene("cornell");
    const ImageMetrics m = directAgreement(ctx(), scene, scene.cameras[0], 160, 120);
    std::printf("[ eval ] cornell direct, rasterizer vs reference: rel L1 %.4f, rel L2 %.4f, relative bias %+.4f, "
                "SSIM %.4f\n", m.relL1, m.relL2, m.meanBias / m.refMean, m.ssim);
    EXPECT_LT(m.relL1, 0.02);
    EXPECT_LT(std::abs(m.meanBias), 0.005 * m.refMean) << "no unit or falloff mismatch";
}

TEST_F(EvalTest, DirectLightAgreesWithReferenceOnVC) {
    const fs::path vc = fs::path(PENUMBRA_SOURCE_DIR) / ".." / "shared" / "assets" / "VC" / "glTF" / "VC.gltf";
    if (!fs::exists(vc)) GTEST_SKIP() << "no ../shared/assets/VC next to the source tree";
    Scene scene = loadScene(vc.string());
    Camera cam;
    cam.eye = {14, 9, 16}, cam.target = {0, 1.5f, 0}, cam.fovy = glm::radians(50.0f);
    const ImageMetrics m = directAgreement(ctx(), scene, cam, 320, 180);
    std::printf("[ eval ] VC direct, rasterizer vs reference: rel L1 %.4f, rel L2 %.4f, relative bias %+.4f, "
                "SSIM %.4f\n", m.relL1, m.relL2, m.meanBias / m.refMean, m.ssim);
    EXPECT_LT(m.relL1, 0.05);
    EXPECT_LT(std::abs(m.meanBias), 0.02 * m.refMean);
}

TEST_F(EvalTest, GiRowsOnCornell) {
    const Scene scene = makeBuiltinScene("cornell");
    const uint32_t w = 64, h = 48;
    ReferenceSettings rs;
    rs.width = w, rs.height = h, rs.spp = 256, rs.progress = false;
    const ReferenceImage ref = renderReference(scene, scene.cameras[0], rs);
    GroundTruth truth{{w, h, ref.rgba(ReferenceAov::Direct)}, {w, h, ref.rgba(ReferenceAov::Indirect)},
                      {w, h, ref.rgba(ReferenceAov::Final)}, ref.covered,
                      ref.relativeNoise(ReferenceAov::Final), ref.relativeNoise(ReferenceAov::Indirect)};
    RenderSettings base;
    base.width = w, base.height = h;
    std::vector<EvalVariant> variants = evalVariants(base);
    ASSERT_GE(variants.size(), 6u);
    EXPECT_EQ(variants[0].technique, "none");
    EXPECT_EQ(variants[1].technique, "rsm full");
    variants.resize(2);
    variants[1].render.rsm.resolution = 128;
    const std::vector<EvalRow> rows = runEval(ctx(), scene, scene.cameras[0], variants, truth, 1, nullptr);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[0].indirect.relL2, 1.0) << "no GI: all of the indirect light is missing";
    EXPECT_NEAR(relativeBias(rows[0].indirect), -1.0, 1e-9);
    EXPECT_LT(rows[1].indirect.relL2, 0.8) << "RSM recovers much of the one-bounce light";
    EXPECT_LT(rows[1].total.relL2, rows[0].total.relL2);
    EXPECT_NEAR(rows[0].direct.relL2, rows[1].direct.relL2, 1e-3) << "GI leaves direct light alone";
    std::printf("[ eval ] cornell 64x48: indirect rel L2 none %.3f, rsm %.3f (reference noise %.3f)\n",
                rows[0].indirect.relL2, rows[1].indirect.relL2, truth.noiseIndirect);
    const std::string table = formatEvalTable(rows, false);
    EXPECT_NE(table.find("| rsm full"), std::string::npos);
}

// ---- bad input to the commands ----

namespace {

class GroundTruthCli : public ::testing::Test {
protected:
    std::string file(const std::string& name) const { return dir_.file(name); }
    ScratchDir dir_{"gt_test"};
};

}  // namespace

TEST_F(GroundTruthCli, ReferenceWritesRadianceAndCompareReadsIt) {
    const std::string ref = file("ref.exr"), other = file("other.exr"), heat = file("heat.png");
    Cli r = runCli(dir_, "reference plane -o " + ref + " --width 16 --height 12 --spp 2 -q --sky none");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    const ImageF img = readExr(ref);
    ASSERT_EQ(img.width, 16u);
    EXPECT_NEAR(img.rgba[(6 * 16 + 8) * 4], 0.5 / 3.14159265358979, 1e-6) << "albedo 0.5, E = 1 from straight above";
    ImageF doubled = img;
    for (float& v : doubled.rgba) v *= 2.0f;
    writeExr(other, 16, 12, doubled.rgba);
    r = runCli(dir_, "compare " + other + " " + ref + " --json -o " + heat);
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_NEAR(j["rel_l1"].get<double>(), 1.0, 1e-6);
    EXPECT_EQ(j["pixels"].get<int>(), 16 * 12);
    EXPECT_TRUE(fs::exists(heat));
    r = runCli(dir_, "compare " + other + " " + ref + " --mask " + ref);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("SSIM"), std::string::npos);
}

TEST_F(GroundTruthCli, BadInputGivesOneErrorLine) {
    const std::string ref = file("ref.exr"), small = file("small.exr"), text = file("text.exr");
    writeExr(ref, 8, 8, std::vector<float>(8 * 8 * 4, 0.5f));
    writeExr(small, 4, 8, std::vector<float>(4 * 8 * 4, 0.5f));
    std::ofstream(text) << "not an image\n";
    expectRefused(dir_, "compare " + file("missing.exr") + " " + ref, "no such file");
    expectRefused(dir_, "compare " + text + " " + ref, "not an OpenEXR file");
    expectRefused(dir_, "compare " + ref + " " + small, "sizes must match");
    expectRefused(dir_, "compare " + ref + " " + ref + " --mask " + small, "--mask");
    expectRefused(dir_, "compare " + ref + " " + ref + " -o " + file("heat.jpg"), ".png");
    expectRefused(dir_, "compare " + ref, "B");
    expectRefused(dir_, "reference plane -o " + file("r.exr") + " --spp 0", "--spp");
    expectRefused(dir_, "reference plane -o " + file("r.exr") + " --bounces 17", "--bounces");
    expectRefused(dir_, "reference plane -o " + file("r.txt"), ".exr");
    expectRefused(dir_, "reference plane -o " + file("r.exr") + " --aov albedo", "albedo");
    expectRefused(dir_, "reference " + file("missing.gltf") + " -o " + file("r.exr"), "missing.gltf");
    expectRefused(dir_, "eval plane --spp 0", "--spp");
}
