// The temporal GI's figures pinned at small sizes with the default settings: cornell's flicker under
// its spot sweep (stability's measurement, src/app/stability.h) and the response to its light going
// out and coming on (src/app/response.h), for RSM and LPV, against the bounds the docs state.
#include <cstdio>

#include "app/response.h"
#include "app/stability.h"
#include "core/gpu_scene.h"
#include "frame/frame_options.h"
#include "gpu_fixture.h"
#include "scene/motion.h"

namespace penumbra::test {
namespace {

class TemporalGiFigures : public GpuTest, public ::testing::WithParamInterface<GiMode> {
protected:
    // Cornell at 96x72 with stability's small maps and the default temporal GI.
    RenderSettings settings() const {
        RenderSettings s;
        s.width = 96;
        s.height = 72;
        s.gi = GetParam();
        s.aov = Aov::Indirect;
        s.shadow.resolution = 512;
        s.rsm.resolution = 256;
        s.lpv.rsmResolution = 512;
        s.lpv.vplResolution = 128;
        return s;
    }
};

std::vector<float> luminance(const std::vector<float>& rgba) {
    std::vector<float> out(rgba.size() / 4);
    for (size_t i = 0; i < out.size(); ++i)
        out[i] = 0.2126f * rgba[4 * i] + 0.7152f * rgba[4 * i + 1] + 0.0722f * rgba[4 * i + 2];
    return out;
}

// 16 still frames settle the history, then 8 frames of the spot's sweep at 30 frames a second: RMS
// flicker of the indirect light at most 0.01 (the true figure of this slow sweep cannot be told from 0).
TEST_P(TemporalGiFigures, CornellsSpotSweepFlickersAtMostOnePercent) {
    const Scene scene = makeBuiltinScene("cornell");
    GpuScene gpu(ctx(), scene);
    const SceneMotion motion(gpu.scene(), scene.cameras[0], gpu.scene().lights, {}, {});
    ASSERT_TRUE(motion.moves());
    Renderer r(ctx(), gpu, settings(), 1);
    std::vector<std::vector<float>> frames;
    for (int i = -16; i < 8; ++i) {
        r.render(frameInputs(motion, std::max(i, 0) / 30.0));
        if (i >= 0) frames.push_back(luminance(r.readHdr()));
    }
    const double rms = flickerRms(frames);
    std::printf("[ cornell flicker ] RMS indirect %.5f\n", rms);
    EXPECT_LE(rms, 0.01);
}

// The light goes out, or comes on, after 16 still frames: the median pixel has 90% of the change after
// two frames and 99% after eight, and the 5th percentile 70% after two.
TEST_P(TemporalGiFigures, CornellsLightFollowsOffAndOnWithinTwoFrames) {
    const Scene scene = makeBuiltinScene("cornell");
    GpuScene gpu(ctx(), scene);
    for (const char* change : {"off", "on"}) {
        Renderer r(ctx(), gpu, settings(), 1);
        const nlohmann::json j = measureResponse(r, scene.cameras[0], parseLightChange(change), scene.lights, 16, 8);
        const nlohmann::json& k2 = j["r"][1];
        const double r8 = j["r"][7]["median"];
        std::printf("[ cornell light %s ] r_2 %.3f (p05 %.3f), r_8 %.3f over %zu pixels\n", change,
                    k2["median"].get<double>(), k2["p05"].get<double>(), r8, j["pixels_changed"].get<size_t>());
        EXPECT_GT(j["pixels_changed"].get<size_t>(), 1000u);
        EXPECT_GE(k2["median"].get<double>(), 0.9);
        EXPECT_GE(k2["p05"].get<double>(), 0.7);
        EXPECT_GE(r8, 0.99);
    }
}

INSTANTIATE_TEST_SUITE_P(Gi, TemporalGiFigures, ::testing::Values(GiMode::Rsm, GiMode::Lpv),
                         [](const auto& info) { return info.param == GiMode::Rsm ? "Rsm" : "Lpv"; });

}  // namespace
}  // namespace penumbra::test
