// A technique that lives outside src/: a constant ambient irradiance, registered by this file's
// static TechniqueRegistration (linked into the test binary) with its settings in
// RenderSettings::extensions, and no edit to the assembly. It contributes under the shared
// irradiance name; the lighting pass sums it with whatever else contributes. Checked against the
// analytic answer: the indirect AOV is albedo / pi * E with E the ambient irradiance, alone or
// added to the RSM's.
#include <cmath>

#include <gtest/gtest.h>

#include "core/names.h"
#include "gpu_fixture.h"
#include "renderer/technique_registry.h"
#include "scene/builders.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

struct AmbientSettings {
    bool enabled = false;
    float irradiance = 0.0f;
};

class AmbientTechnique : public Technique {
public:
    AmbientTechnique(const TechniqueBuild& b, const AmbientSettings& s)
        : settings_(s),
          image_(b.alloc, {VK_FORMAT_R32G32B32A32_SFLOAT, b.core.width, b.core.height, 1,
                           VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, "test-ambient"}) {}
    const char* name() const override { return "test-ambient"; }
    bool contributesIrradiance() const override { return true; }
    void addPasses(const FrameContext& f) override {
        const ImageHandle h = f.graph.import(image_);
        const float e = settings_.irradiance;
        f.graph.pass("test.ambient", PassKind::Transfer).use(h, Use::TransferDst).record([h, e](PassContext& c) {
            const VkClearColorValue value{{e, e, e, 1.0f}};
            const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
            vkCmdClearColorImage(c.cmd, c.image(h).handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &value, 1, &range);
        });
        f.graph.contribute(names::kIrradianceContribution, h);
    }

private:
    AmbientSettings settings_;
    vk::Image image_;
};

constexpr const char* kName = "test-ambient";

const TechniqueRegistration registration{[] {
    TechniqueEntry e{kName, 65};  // after the built-in GI, before the temporal GI and the lighting
    e.parts = kPartCamera;
    e.enabled = [](const RenderSettings& s) {
        const AmbientSettings* a = s.extension<AmbientSettings>(kName);
        return a && a->enabled;
    };
    e.create = [](const TechniqueBuild& b, const RenderSettings& s) {
        return std::make_unique<AmbientTechnique>(b, *s.extension<AmbientSettings>(kName));
    };
    return e;
}()};

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
