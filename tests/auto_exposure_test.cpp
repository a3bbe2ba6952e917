// `--exposure auto` on lavapipe: the GPU's exposure against a double-precision sum over the same
// read-back image (geometry pixels only; a bright sky around them must not count).
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "lighting/lighting_technique.h"
#include "scene/builders.h"
#include "test_renderer.h"

namespace penumbra::test {
namespace {

class AutoExposureTest : public GpuTest {};

gpu::AutoExposureState readState(TestRenderer& r) {
    const std::vector<uint8_t> bytes =
        r.commands().readBuffer(r.find<LightingTechnique>()->autoExposure().state(), sizeof(gpu::AutoExposureState));
    gpu::AutoExposureState state;
    std::memcpy(&state, bytes.data(), sizeof(state));
    return state;
}

TEST_F(AutoExposureTest, GeometryLogAverageMapsToMiddleGrey) {
    const Scene scene = makeBuiltinScene("cornell");
    Camera camera = scene.cameras[0];
    camera.fovy = 2.0f;  // wide: the open front shows the sky around the box
    RenderSettings s;
    s.width = 64, s.height = 48;
    s.giTemporal = false;
    s.autoExposure = true;
    s.lighting.sky.kind = SkyKind::Uniform;
    s.lighting.sky.uniformRadiance = glm::vec3(50.0f);
    TestRenderer r(ctx(), scene, s);
    r.render(camera);
    const std::vector<float> hdr = r.readHdr();
    double sum = 0.0;
    size_t geometry = 0, sky = 0;
    for (size_t i = 0; i < hdr.size() / 4; ++i) {
        const float* c = &hdr[i * 4];
        if (c[3] < 0.5f) {
            ++sky;
            continue;
        }
        sum += std::log(1e-6 + 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]);
        ++geometry;
    }
    ASSERT_GT(geometry, 0u);
    ASSERT_GT(sky, 0u) << "the view should show sky around the box";
    const double expected = 0.18 / std::exp(sum / double(geometry));
    const gpu::AutoExposureState state = readState(r);
    EXPECT_EQ(state.valid, 1u);
    EXPECT_NEAR(state.exposure, expected, 1e-4 * expected);
    EXPECT_NEAR(state.logAverage, sum / double(geometry), 1e-4);

    // Another view: its target is approached exponentially in log space, one frame's step.
    camera.fovy = 0.6f;
    r.render(camera);
    const std::vector<float> next = r.readHdr();
    double nextSum = 0.0;
    size_t nextGeometry = 0;
    for (size_t i = 0; i < next.size() / 4; ++i)
        if (const float* c = &next[i * 4]; c[3] >= 0.5f)
            nextSum += std::log(1e-6 + 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]), ++nextGeometry;
    const double target = std::log(0.18) - nextSum / double(nextGeometry);
    const double rate = 1.0 - std::exp(-double(AutoExposure::kFrameSeconds) / AutoExposure::kTauSeconds);
    const double adapted = std::log(expected) + (target - std::log(expected)) * rate;
    ASSERT_GT(std::abs(target - std::log(expected)), 0.05) << "the two views should differ";
    EXPECT_NEAR(std::log(readState(r).exposure), adapted, 1e-4);
}

}  // namespace
}  // namespace penumbra::test
