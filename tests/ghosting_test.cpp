// Ghosting of the temporal GI behind moving geometry (src/app/ghosting.h): the moving Cornell box
// moves as its animation says, the disocclusion mask is what its definition says, and the indirect
// light where the box has just left stays close to the converged still image of that instant.
#include <gtest/gtest.h>

#include "app/ghosting.h"
#include "core/gpu_scene.h"
#include "gpu_fixture.h"
#include "scene/animation.h"

namespace penumbra::test {
namespace {

float boxX(const Scene& scene, double t) { return nodeWorldTransforms(scene, t, {})[0][3].x; }

TEST(MovingCornell, TheBoxSlidesAtOneMetreASecondAndComesBack) {
    const Scene scene = makeBuiltinScene("cornell-moving");
    ASSERT_EQ(scene.instances.size(), 2u);
    EXPECT_NEAR(boxX(scene, 0.75) - boxX(scene, 0.25), 0.5f, 1e-5f);
    EXPECT_NEAR(boxX(scene, 2.25) - boxX(scene, 1.75), -0.5f, 1e-5f);
    EXPECT_NEAR(boxX(scene, 3.0), boxX(scene, 0.0), 1e-5f);  // it loops without a jump
}

TEST(Ghosting, DisoccludedPixelsAreThoseNearerTwoFramesEarlier) {
    const float inf = std::numeric_limits<float>::infinity();
    const std::vector<float> before{1.0f, 1.0f, 2.0f, inf, 1.95f}, now{2.0f, 1.0f, 2.0f, 2.0f, 2.0f};
    // Pixel 0: a box at 1 m, now the wall at 2 m. 4: 2.5% nearer is within the tolerance.
    EXPECT_EQ(disoccludedPixels(before, now), std::vector<size_t>{0});
}

class GhostingTest : public GpuTest {};

// Cornell's box sliding at 1 m/s, 30 frames a second, the default RSM: where the box stood two
// frames earlier, the indirect light is within 10% (relative L1) of the converged still image.
TEST_F(GhostingTest, WhereTheBoxLeftTheIndirectIsCloseToTheStillImage) {
    const Scene scene = makeBuiltinScene("cornell-moving");
    GpuScene gpu(ctx(), scene);
    const SceneMotion motion(gpu.scene(), scene.cameras[0], gpu.scene().lights, {}, {});
    RenderSettings s;
    s.width = 160;
    s.height = 120;
    s.gi = GiMode::Rsm;
    s.aov = Aov::Indirect;
    s.shadow.resolution = 512;
    s.rsm.resolution = 256;
    const nlohmann::json j = measureGhosting(ctx(), gpu, s, motion, {0.0, 30.0, 16, 2, 32});
    std::printf("[ ghosting ] %zu pixels, rel L1 %.4f, %.3f of them beyond 10%%\n", j["pixels"].get<size_t>(),
                j["rel_l1"].get<double>(), j["share_beyond_10_percent"].get<double>());
    EXPECT_GT(j["pixels"].get<size_t>(), 40u);
    EXPECT_LT(j["rel_l1"].get<double>(), 0.10);
}

}  // namespace
}  // namespace penumbra::test
