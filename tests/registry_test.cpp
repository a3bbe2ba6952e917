// A technique that lives outside src/: a constant ambient irradiance, registered by this file's
// static TechniqueRegistration (linked into the test binary) with its settings in
// RenderSettings::extensions, and no edit to the assembly. It contributes under the shared
// irradiance name; the lighting pass sums it with whatever else contributes. Checked against the
// analytic answer: the indirect AOV is albedo / pi * E with E the ambient irradiance, alone or
// added to the RSM's.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "ambient_technique.h"
#include "app/cli_app.h"
#include "gpu_fixture.h"
#include "renderer/technique_registry.h"
#include "renderer/render_options.h"
#include "scene/builders.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

constexpr const char* kName = kAmbientName;

class RegistryTest : public GpuTest {
protected:
    FloatImage renderCornell(RenderSettings s, Aov aov) {
        const Scene scene = makeBuiltinScene("cornell");
        s.width = 64, s.height = 48, s.aov = aov;
        Renderer r(ctx(), scene, s);
        r.render(scene.cameras.at(0));
        return {s.width, s.height, r.readHdr()};
    }
};

// |a - b| within a relative and an absolute float tolerance, over RGB of every pixel.
size_t mismatches(const FloatImage& a, const FloatImage& b, const std::function<float(size_t)>& expectedDiff) {
    size_t bad = 0;
    for (size_t i = 0; i < a.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        const float want = expectedDiff(i);
        if (std::abs((a.rgba[i] - b.rgba[i]) - want) > 1e-5f + 1e-5f * std::abs(a.rgba[i])) ++bad;
    }
    return bad;
}

}  // namespace

TEST_F(RegistryTest, OutsideTechniqueIsRegisteredAndOrdered) {
    const TechniqueRegistry& r = TechniqueRegistry::instance();
    ASSERT_NE(r.find(kName), nullptr);
    std::vector<std::string> frame;
    for (const TechniqueEntry& e : r.entries()) frame.push_back(e.name);
    const auto at = [&](const std::string& n) { return std::find(frame.begin(), frame.end(), n) - frame.begin(); };
    EXPECT_LT(at("lpv"), at(kName));
    EXPECT_LT(at(kName), at("lighting"));
    // The shadow technique is built after the deep shadow maps it reads at build time.
    std::vector<std::string> build;
    for (const TechniqueEntry* e : r.buildOrder()) build.push_back(e->name);
    EXPECT_LT(std::find(build.begin(), build.end(), "dsm"), std::find(build.begin(), build.end(), "shadow"));
    EXPECT_THROW(TechniqueRegistry::instance().add(*r.find(kName)), std::logic_error);
}

TEST_F(RegistryTest, AmbientAloneGivesAlbedoOverPiTimesIrradiance) {
    constexpr float kE = 0.75f;
    RenderSettings s;
    s.giTemporal = false;  // the contribution as the lighting reads it, neither accumulated nor filtered
    s.extension<AmbientSettings>(kName) = {true, kE};
    const FloatImage indirect = renderCornell(s, Aov::Indirect);
    const FloatImage albedo = renderCornell(s, Aov::Albedo);
    const FloatImage zero{albedo.width, albedo.height, std::vector<float>(albedo.rgba.size(), 0.0f)};
    size_t lit = 0;
    for (size_t i = 0; i < albedo.rgba.size(); i += 4) lit += albedo.rgba[i] > 0.0f;
    EXPECT_GT(lit, albedo.rgba.size() / 8) << "the box covers the image";
    EXPECT_EQ(mismatches(indirect, zero, [&](size_t i) { return albedo.rgba[i] / float(M_PI) * kE; }), 0u);
}

TEST_F(RegistryTest, AmbientAddsToTheRsmContribution) {
    constexpr float kE = 0.5f;
    RenderSettings rsm;
    rsm.gi = GiMode::Rsm;
    rsm.giTemporal = false;  // the sum as the lighting reads it, not filtered
    RenderSettings both = rsm;
    both.extension<AmbientSettings>(kName) = {true, kE};
    const FloatImage alone = renderCornell(rsm, Aov::Indirect);
    const FloatImage summed = renderCornell(both, Aov::Indirect);
    const FloatImage albedo = renderCornell(rsm, Aov::Albedo);
    double rsmEnergy = 0.0;
    for (size_t i = 0; i < alone.rgba.size(); i += 4) rsmEnergy += alone.rgba[i];
    EXPECT_GT(rsmEnergy, 0.0) << "the RSM contributes too";
    EXPECT_EQ(mismatches(summed, alone, [&](size_t i) { return albedo.rgba[i] / float(M_PI) * kE; }), 0u);
}

// The technique's option table alone gives it a CLI option with its range and help.
TEST(RegistryOptions, OutsideTechniqueGetsItsCliOptionRangeAndHelp) {
    Cli cli;
    cli.app.parse(std::vector<std::string>{"0.25", "--ambient-irradiance", "on", "--ambient", "cornell", "render"});
    EXPECT_TRUE(ambientSettings(cli.renderSettings).enabled);
    EXPECT_FLOAT_EQ(ambientSettings(cli.renderSettings).irradiance, 0.25f);
    const std::string help = cli.renderCmd->help();
    EXPECT_NE(help.find("--ambient-irradiance"), std::string::npos) << help;
    EXPECT_NE(help.find("[0, 1000]"), std::string::npos) << help;
    Cli refused;
    try {
        refused.app.parse(std::vector<std::string>{"-1", "--ambient-irradiance", "cornell", "render"});
        ADD_FAILURE() << "--ambient-irradiance -1 was taken";
    } catch (const CLI::ParseError& e) {
        EXPECT_NE(std::string(e.what()).find("--ambient-irradiance"), std::string::npos) << e.what();
    }
}

// `bench` writes the technique's settings under its name in the JSON, from its table's keys.
TEST(RegistryOptions, OutsideTechniqueShowsInBenchJson) {
    const std::filesystem::path json = std::filesystem::temp_directory_path() / "penumbra_registry_bench.json";
    Cli cli;
    cli.app.parse(std::vector<std::string>{json.string(), "--json", "0", "--warmup", "2", "--frames", "24", "--height",
                                           "32", "--width", "0.5", "--ambient-irradiance", "on", "--ambient",
                                           "cornell", "bench"});
    cli.vk.validate = cli.vk.syncValidation = true;
    EXPECT_EQ(cli.run(), 0);
    nlohmann::json j;
    std::ifstream(json) >> j;
    EXPECT_EQ(j.at("settings").at(kName).at("irradiance").get<double>(), 0.5);
    EXPECT_EQ(j.at("settings").at(kName).at("enabled").get<bool>(), true);
    std::filesystem::remove(json);
}

// A per-frame change of the technique's option is classified per-frame by its row, allocates
// nothing, and the next frame shows it (the indirect light is albedo / pi * E with the new E).
TEST_F(RegistryTest, OutsideTechniquePerFrameChangeAllocatesNothing) {
    const Scene scene = makeBuiltinScene("cornell");
    RenderSettings s;
    s.width = 64, s.height = 48, s.aov = Aov::Indirect;
    s.giTemporal = false;  // the next frame shows the new value alone, not blended into a history
    ambientSettings(s) = {true, 0.5f};
    Renderer r(ctx(), scene, s);
    r.render(scene.cameras.at(0));
    RenderSettings next = s;
    ambientSettings(next).irradiance = 1.5f;
    const SettingsDiff diff = diffSettings(s, next);
    ASSERT_EQ(diff.flags, std::vector<std::string>{"--ambient-irradiance"});
    const uint64_t before = r.allocator().allocations();
    EXPECT_EQ(r.apply(next), SettingsChange::PerFrame);
    r.render(scene.cameras.at(0));
    EXPECT_EQ(r.allocator().allocations(), before);
    const FloatImage indirect{s.width, s.height, r.readHdr()};
    const FloatImage albedo = renderCornell(s, Aov::Albedo);
    const FloatImage zero{albedo.width, albedo.height, std::vector<float>(albedo.rgba.size(), 0.0f)};
    EXPECT_EQ(mismatches(indirect, zero, [&](size_t i) { return albedo.rgba[i] / float(M_PI) * 1.5f; }), 0u);
    EXPECT_EQ(renderSettingsJson(next).at(kName).at("irradiance").get<double>(), 1.5);
}
