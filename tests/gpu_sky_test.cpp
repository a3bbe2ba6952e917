// The sky on the GPU (lighting/gpu_sky.h) against the CPU's sky (core/sky.h), which evaluates
// Preetham's model and integrates its SH in double precision: the analytic sky's table texel by
// texel, its background at the background's texel centres and its SH against Sky::sh(), for suns
// from near the horizon to overhead and the whole range of turbidity; and a sky made on the CPU,
// uploaded as it is.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/frame_graph.h"
#include "gpu_fixture.h"
#include "lighting/gpu_sky.h"
#include "readback.h"
#include "renderer/renderer.h"
#include "scene/scene.h"
#include "vk/commands.h"
#include "vk/memory.h"

namespace penumbra::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Single-precision evaluation against double: a texel's channels within this share of its largest
// channel (cancellations in the XYZ to RGB conversion and exp() of the Perez terms in float).
constexpr double kTexelTolerance = 2e-5;
// Each SH coefficient within this share of the sky's mean radiance (coefficient 0 over 0.282): a
// sum over 32768 texels in float, by rows and then over the rows.
constexpr double kShTolerance = 3e-6;

class GpuSkyTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        alloc_ = std::make_unique<vk::Allocator>(ctx());
        cmd_ = std::make_unique<vk::CommandContext>(*alloc_);
        sky_ = std::make_unique<GpuSky>(*alloc_, *cmd_);
    }
    void TearDown() override {
        sky_.reset();
        cmd_.reset();
        alloc_.reset();
        GpuTest::TearDown();
    }
    // One frame of the GPU sky's passes, as the lighting module's update adds them.
    void run() {
        FrameGraph graph(ctx());
        sky_->addTo(graph);
        cmd_->submitAndWait([&](VkCommandBuffer c) { graph.execute(c, nullptr); });
    }
    std::vector<glm::vec3> table() {
        const std::vector<uint8_t> bytes = cmd_->readImage(sky_->table(), 16);
        std::vector<glm::vec3> out(bytes.size() / 16);
        for (size_t i = 0; i < out.size(); ++i) out[i] = {f32(bytes, 4 * i), f32(bytes, 4 * i + 1), f32(bytes, 4 * i + 2)};
        return out;
    }
    std::vector<glm::vec3> background() {
        const std::vector<uint8_t> bytes = cmd_->readImage(sky_->background(), 8);
        std::vector<glm::vec3> out(bytes.size() / 8);
        for (size_t i = 0; i < out.size(); ++i)
            out[i] = {half(bytes, 4 * i), half(bytes, 4 * i + 1), half(bytes, 4 * i + 2)};
        return out;
    }
    std::array<glm::vec3, 9> sh() {
        const std::vector<uint8_t> bytes = cmd_->readBuffer(sky_->sh(), 9 * 16);
        std::array<glm::vec3, 9> out;
        for (size_t k = 0; k < 9; ++k) out[k] = {f32(bytes, 4 * k), f32(bytes, 4 * k + 1), f32(bytes, 4 * k + 2)};
        return out;
    }

    std::unique_ptr<vk::Allocator> alloc_;
    std::unique_ptr<vk::CommandContext> cmd_;
    std::unique_ptr<GpuSky> sky_;
};

// The background's texel (r, c) looks along the layout's direction at its row's mid polar angle.
glm::vec3 backgroundDirection(uint32_t r, uint32_t c) {
    const double theta = kPi * (r + 0.5) / GpuSky::kHeight, phi = skyAzimuth(c + 0.5, GpuSky::kWidth);
    return glm::vec3(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
}

double largest(const glm::dvec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

// Worst differences over the cases, for the log.
struct Worst {
    double texel = 0.0, background = 0.0, sh = 0.0;
};

void checkAgainstCpu(const Sky& cpu, const std::vector<glm::vec3>& table, const std::vector<glm::vec3>& background,
                     const std::array<glm::vec3, 9>& sh, const std::string& label, Worst& worst) {
    ASSERT_EQ(cpu.table().width, GpuSky::kWidth);
    ASSERT_EQ(table.size(), cpu.table().texels.size());
    size_t lit = 0;
    for (size_t i = 0; i < table.size(); ++i) {
        const glm::dvec3 expected(cpu.table().texels[i]), got(table[i]);
        const double scale = largest(expected);
        lit += scale > 0.0;
        const double error = largest(got - expected);
        worst.texel = std::max(worst.texel, error / std::max(scale, 1e-30));
        ASSERT_LE(error, kTexelTolerance * scale + 1e-30) << label << " texel " << i;
    }
    EXPECT_EQ(lit, table.size() / 2) << label << ": the upper half of the table is lit, the lower black";
    // The background is stored in half floats, rounded as the device rounds them (Vulkan leaves the mode
    // to it; lavapipe truncates): within one of their steps (2^-10 of the value) after the same tolerance.
    for (uint32_t r = 0; r < GpuSky::kHeight; ++r)
        for (uint32_t c = 0; c < GpuSky::kWidth; ++c) {
            const glm::dvec3 expected(cpu.radiance(backgroundDirection(r, c)));
            const glm::dvec3 got(background[r * GpuSky::kWidth + c]);
            const double scale = largest(expected), error = largest(got - expected);
            worst.background = std::max(worst.background, error / std::max(scale, 1e-30));
            ASSERT_LE(error, (kTexelTolerance + std::ldexp(1.0, -10)) * scale + 1e-30) << label << " row " << r << " column " << c;
        }
    const std::array<glm::dvec3, 9> expected = cpu.sh();
    const double mean = largest(expected[0]);
    ASSERT_GT(mean, 0.0);
    for (size_t k = 0; k < 9; ++k) {
        const double error = largest(glm::dvec3(sh[k]) - expected[k]);
        worst.sh = std::max(worst.sh, error / mean);
        EXPECT_LE(error, kShTolerance * mean) << label << " coefficient " << k;
    }
}

TEST_F(GpuSkyTest, AnalyticSkyMatchesTheCpuSkyTexelByTexel) {
    Worst worst;
    for (const float turbidity : {2.0f, 3.0f, 6.0f, 10.0f})
        for (const double elevation : {2.0, 10.0, 35.0, 70.0, 90.0}) {
            const double e = elevation * kPi / 180.0, azimuth = 0.4 + elevation / 30.0;
            const glm::vec3 toSun(std::cos(e) * std::sin(azimuth), std::sin(e), -std::cos(e) * std::cos(azimuth));
            const AnalyticSkyModel model = AnalyticSkyModel::make(turbidity, toSun, 4.0f);
            sky_->set(model);
            run();
            const std::string label = "T " + std::to_string(turbidity) + " elevation " + std::to_string(elevation);
            checkAgainstCpu(Sky::analytic(model), table(), background(), sh(), label, worst);
            if (HasFatalFailure()) return;
        }
    std::printf("[ gpu sky ] worst relative difference: table %.2e, background %.2e, SH %.2e of coefficient 0\n",
                worst.texel, worst.background, worst.sh);
}

// The user's scale reaches the GPU's sky as the CPU's makeSky applies it.
TEST_F(GpuSkyTest, ScaledAnalyticSkyIsTheCpuSkyScaled) {
    SkySettings settings;
    settings.kind = SkyKind::Analytic;
    settings.scale = 0.25f;
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.3f, -0.6f, 0.5f));
    sun.intensity = 3.0f;
    std::vector<std::string> warnings;
    const std::optional<AnalyticSkyModel> model = makeAnalyticSky(settings, {sun}, warnings);
    ASSERT_TRUE(model);
    sky_->set(*model);
    run();
    Worst worst;
    checkAgainstCpu(makeSky(settings, {sun}, warnings), table(), background(), sh(), "scale 0.25", worst);
    EXPECT_TRUE(warnings.empty());
}

// A sky made on the CPU (here uniform) is uploaded: its background as the CPU evaluates it, its SH
// as Sky::sh() gives them. Then an analytic sky replaces it, and the uniform sky comes back.
TEST_F(GpuSkyTest, CpuSkyIsUploadedAndAnalyticSkyReplacesIt) {
    const Sky uniform = Sky::uniform(glm::vec3(0.5f, 1.0f, 2.0f));
    sky_->set(uniform, 0);
    run();
    const std::vector<glm::vec3> b = background();
    for (uint32_t r = 0; r < GpuSky::kHeight; ++r)
        EXPECT_EQ(b[r * GpuSky::kWidth + 7], r < GpuSky::kHeight / 2 ? glm::vec3(0.5f, 1.0f, 2.0f) : glm::vec3(0.0f))
            << "row " << r;
    const std::array<glm::dvec3, 9> expected = uniform.sh();
    std::array<glm::vec3, 9> got = sh();
    for (size_t k = 0; k < 9; ++k) EXPECT_EQ(got[k], glm::vec3(expected[k])) << "coefficient " << k;

    sky_->set(AnalyticSkyModel::make(3.0f, glm::normalize(glm::vec3(0.2f, 0.7f, -0.3f)), 2.0f));
    run();
    EXPECT_NE(sh()[0], glm::vec3(expected[0]));
    sky_->set(uniform, 1);
    run();
    got = sh();
    for (size_t k = 0; k < 9; ++k) EXPECT_EQ(got[k], glm::vec3(expected[k])) << "coefficient " << k;
}

// --sky-sun-illuminance with a sky that does not follow the sun: one warning, the sky as given.
TEST_F(GpuSkyTest, SunIlluminanceOfAnotherSkyIsIgnoredWithAWarning) {
    const Scene plane = makeBuiltinScene("plane");
    RenderSettings s;
    s.width = 16, s.height = 16;
    s.lighting.sky.kind = SkyKind::Uniform;
    s.lighting.sky.sunIlluminance = 3.0f;
    Renderer r(ctx(), plane, s);
    r.render(plane.cameras.at(0));
    size_t said = 0;
    for (const std::string& w : r.warnings()) said += w == "--sky-sun-illuminance scales the analytic sky only: ignored";
    EXPECT_EQ(said, 1u);
}

}  // namespace
}  // namespace penumbra::test
