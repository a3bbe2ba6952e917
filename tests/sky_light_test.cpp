// The sky's light with occlusion (src/sky_light) against analytic answers: a uniform sky of radiance
// L over the upper hemisphere gives an open upward plane pi L, and nothing inside a closed room. The
// sky is published by a test technique from its SH coefficients (core/sky.h's basis: the l = 1
// coefficient along +Y is L sqrt(3 pi) / 2; the l = 2 ones of a hemisphere vanish).
#include <cmath>

#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "readback.h"
#include "renderer/technique_registry.h"
#include "sky_light/sky_light_technique.h"
#include "test_renderer.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

// The uniform sky of radiance L over the upper hemisphere, black below.
SkyLight uniformSky(float radiance) {
    SkyLight sky;
    sky.enabled = true;
    sky.radianceSh[0] = glm::vec3(radiance * std::sqrt(float(M_PI)));
    sky.radianceSh[1] = glm::vec3(radiance * std::sqrt(3.0f * float(M_PI)) / 2.0f);
    sky.generation = 1;
    return sky;
}

SkyLight testSky;

class SkyPublisher : public Technique {
public:
    explicit SkyPublisher(Blackboard& board) : board_(board) {}
    ~SkyPublisher() override { board_.dropOwner(this); }
    const char* name() const override { return "test-sky"; }
    void update(const FrameContext& f) override { f.board.put(names::kSkyLight, &testSky, this); }
    void addPasses(const FrameContext&) override {}

private:
    Blackboard& board_;
};

const TechniqueRegistration skyRegistration{[] {
    TechniqueEntry e{"test-sky", 5};
    e.parts = kPartCamera;
    e.create = [](const TechniqueBuild& b, const RenderSettings&) { return std::make_unique<SkyPublisher>(b.board); };
    return e;
}()};

class SkyLightTest : public GpuTest {
protected:
    // The sky's irradiance per pixel (RGBA32F) of a frame of `scene` from its first camera, its
    // lights off.
    std::vector<float> skyIrradiance(Scene scene, const SkyLight& sky, RenderSettings s = {}) {
        for (Light& l : scene.lights) l.intensity = 0.0f;
        testSky = sky;
        s.width = 64, s.height = 48, s.giTemporal = false;
        TestRenderer r(ctx(), scene, s);
        r.render(scene.cameras.at(0));
        SkyLightTechnique* t = r.find<SkyLightTechnique>();
        EXPECT_NE(t, nullptr);
        if (!t) return {};
        const std::vector<uint8_t> bytes = r.commands().readImage(t->irradiance(), 16);
        std::vector<float> out(bytes.size() / 4);
        for (size_t i = 0; i < out.size(); ++i) out[i] = f32(bytes, i);
        direct_ = r.readHdr();
        return out;
    }
    std::vector<float> direct_;  // the last frame's direct AOV
};

}  // namespace

TEST_F(SkyLightTest, UniformSkyGivesAnOpenPlanePiL) {
    constexpr float kL = 0.8f;
    RenderSettings s;
    s.aov = Aov::Direct;
    const std::vector<float> e = skyIrradiance(makeBuiltinScene("plane"), uniformSky(kL), s);
    ASSERT_EQ(e.size(), 64u * 48u * 4u);
    size_t checked = 0;
    for (size_t i = 0; i < e.size(); i += 4) {
        if (e[i + 3] < 0.5f) continue;  // the background
        ++checked;
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(e[i + c], float(M_PI) * kL, 1e-4f) << "pixel " << i / 4;
            // The lighting adds albedo / pi times it to the direct light (the plane's albedo 0.5).
            EXPECT_NEAR(direct_[i + c], 0.5f * kL, 1e-4f) << "pixel " << i / 4;
        }
    }
    EXPECT_GT(checked, 64u * 48u / 2) << "the plane covers most of the view";
}

TEST_F(SkyLightTest, NothingOfAUniformSkyReachesInsideTheClosedRoom) {
    const float open = float(M_PI);  // the open plane's irradiance under radiance 1
    const std::vector<float> e = skyIrradiance(makeBuiltinScene("room"), uniformSky(1.0f));
    ASSERT_EQ(e.size(), 64u * 48u * 4u);
    float most = 0.0f;
    size_t surfaces = 0;
    for (size_t i = 0; i < e.size(); i += 4) {
        if (e[i + 3] < 0.5f) continue;
        ++surfaces;
        for (int c = 0; c < 3; ++c) most = std::max(most, e[i + c]);
    }
    EXPECT_EQ(surfaces, 64u * 48u) << "the room's walls fill the view";
    EXPECT_LE(most, 1e-3f * open);
}

TEST_F(SkyLightTest, WithoutVisibilityTheRoomSeesTheWholeSky) {
    // The same room with --sky-visibility none: the floor, facing up, gets the open plane's pi L, so
    // the closed room's darkness above is the occlusion's doing.
    RenderSettings s;
    s.skyLight.visibility = SkyVisibility::None;
    const std::vector<float> e = skyIrradiance(makeBuiltinScene("room"), uniformSky(1.0f), s);
    ASSERT_EQ(e.size(), 64u * 48u * 4u);
    float most = 0.0f;
    for (size_t i = 0; i < e.size(); i += 4) most = std::max(most, e[i + 1]);
    EXPECT_NEAR(most, float(M_PI), 1e-3f);
}
