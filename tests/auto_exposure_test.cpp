// `--exposure auto` on lavapipe: the GPU's exposure against a double-precision sum over the same
// read-back image (geometry pixels only; a bright sky around them must not count), over all of them
// and over a percentile window of an image that is nearly half black.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "lighting/lighting_bindings.h"
#include "lighting/lighting_options.h"
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
    // All the geometry's pixels: this checks the plain log-average, which the window 0,100 meters (the
    // default window leaves the darkest half out: the percentile window's test below checks it).
    s.lighting.exposureLowPercentile = 0.0f, s.lighting.exposureHighPercentile = 100.0f;
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

// A point light beside a wall over a plane, no GI, no sky: the wall's shadow (black) covers nearly half
// of the geometry, and the lit half falls off over more than 4 EV, across some 15 of the histogram's bins.
Scene shadowedPlane() {
    Scene s;
    s.name = "shadowed-plane";
    const uint32_t grey = addMaterial(s, glm::vec3(0.5f));
    addQuad(s, {-4, 0, -4}, {0, 0, 8}, {8, 0, 0}, grey);                 // facing +y
    addBox(s, {0.0f, 0.65f, 0.0f}, {0.1f, 0.65f, 4.0f}, 0.0f, grey);  // the wall, lower than the light
    Light lamp;
    lamp.type = LightType::Point;
    lamp.position = {-3.0f, 1.5f, 0.0f};
    lamp.intensity = 10.0f;
    lamp.name = "lamp";
    s.lights.push_back(lamp);
    s.computeBounds();
    return s;
}

constexpr double kEvPerBin = (EXPOSURE_MAX_EV - EXPOSURE_MIN_EV) / EXPOSURE_BINS;  // 0.3125

// log2(1e-6 + luminance) of the geometry pixels, as exposure_reduce.comp meters them, ascending.
std::vector<double> geometryEv(const std::vector<float>& hdr) {
    std::vector<double> ev;
    for (size_t i = 0; i < hdr.size() / 4; ++i)
        if (const float* c = &hdr[i * 4]; c[3] >= 0.5f)
            ev.push_back(std::log2(1e-6 + 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]));
    std::sort(ev.begin(), ev.end());
    return ev;
}

// Pixel k of the ascending `ev` holds ranks [k, k + 1); the window [low n, high n] weighs each by its overlap.
double overlap(double first, double last, double low, double high) {
    return std::max(0.0, std::min(last, high) - std::max(first, low));
}

struct WindowMeans {
    double exact = 0.0;      // the trimmed mean of the pixels themselves
    double binned = 0.0;     // what the histogram gives: a cut bin's share at its pixels' mean
    double quantised = 0.0;  // the most they can differ: a cut bin's share times its pixels' spread
};

WindowMeans windowMeans(const std::vector<double>& ev, double lowPercentile, double highPercentile) {
    const double n = double(ev.size()), low = lowPercentile / 100.0 * n, high = highPercentile / 100.0 * n;
    WindowMeans m;
    for (size_t k = 0; k < ev.size(); ++k) m.exact += overlap(double(k), double(k + 1), low, high) * ev[k];
    struct Bin {
        double first = 0.0, count = 0.0, sum = 0.0, lo = 1e30, hi = -1e30;
    };
    std::map<int, Bin> bins;  // by index, ascending like `ev`
    for (size_t k = 0; k < ev.size(); ++k) {
        const int index = std::clamp(int((ev[k] - EXPOSURE_MIN_EV) / kEvPerBin), 0, EXPOSURE_BINS - 1);
        Bin& b = bins.try_emplace(index, Bin{double(k)}).first->second;
        b.count += 1.0, b.sum += ev[k], b.lo = std::min(b.lo, ev[k]), b.hi = std::max(b.hi, ev[k]);
    }
    for (const auto& [index, b] : bins) {
        const double weight = overlap(b.first, b.first + b.count, low, high);
        m.binned += weight * b.sum / b.count;
        if (weight > 0.0 && weight < b.count) m.quantised += weight * (b.hi - b.lo);
    }
    const double windowWeight = high - low;
    m.exact /= windowWeight, m.binned /= windowWeight, m.quantised /= windowWeight;
    return m;
}

TEST_F(AutoExposureTest, PercentileWindowMatchesADoublePrecisionTrimmedMean) {
    const Scene scene = shadowedPlane();
    Camera camera;
    camera.eye = {0.0f, 9.0f, 0.0f};
    camera.target = {0.0f, 0.0f, 0.0f};
    camera.up = {0.0f, 0.0f, -1.0f};
    camera.fovy = glm::radians(50.0f);
    RenderSettings s;
    s.width = 64, s.height = 48;
    s.giTemporal = false;
    s.autoExposure = true;
    s.lighting.sky.kind = SkyKind::None;
    TestRenderer r(ctx(), scene, s);
    r.render(camera);
    const std::vector<double> ev = geometryEv(r.readHdr());
    ASSERT_GT(ev.size(), 1000u);
    const double blackEv = std::log2(1e-6);
    const double black = double(std::count(ev.begin(), ev.end(), blackEv)) / double(ev.size());
    ASSERT_GT(black, 0.35) << "the wall's shadow should cover a large part of the plane";
    ASSERT_LT(black, 0.5) << "and less than the default window leaves out";
    ASSERT_GT(ev.back() - ev[size_t(black * double(ev.size()))], 4.0) << "the lit strip should span bins";

    // The first frame takes the default window's target at once.
    const LightingSettings defaults;
    const gpu::AutoExposureState first = readState(r);
    const WindowMeans d = windowMeans(ev, defaults.exposureLowPercentile, defaults.exposureHighPercentile);
    EXPECT_EQ(first.valid, 1u);
    EXPECT_NEAR(std::log2(first.exposure), std::log2(0.18) - d.exact, d.quantised + 1e-4);
    EXPECT_GT(d.exact - windowMeans(ev, 0.0, 100.0).exact, 6.0) << "without the window black pulls the mean down";

    // Each window against the pixels' trimmed mean, within the bins' quantisation: a cut bin (at most
    // two) counts at its pixels' mean, which is at most their spread (under a bin, 0.3125 EV) from the
    // mean of those the window takes; whole bins are exact (their in-bin positions are summed to
    // 2.4e-6 EV). The histogram's own arithmetic agrees with the binned mean in double to 1e-4.
    const double ln2 = std::log(2.0);
    const std::vector<std::pair<float, float>> windows{
        {defaults.exposureLowPercentile, defaults.exposureHighPercentile},
        {0.0f, 100.0f},
        {75.0f, 95.0f},
        {72.5f, 99.5f}};
    for (const auto& [low, high] : windows) {
        s.lighting.exposureLowPercentile = low, s.lighting.exposureHighPercentile = high;
        r.apply(s);
        r.render(camera);
        const WindowMeans m = windowMeans(geometryEv(r.readHdr()), low, high);
        const double metered = readState(r).logAverage / ln2;
        std::printf("[ exposure ] window %g-%g: metered %.5f EV, trimmed mean %.5f EV (|error| %.5f, quantisation "
                    "bound %.5f), binned %.5f EV\n",
                    low, high, metered, m.exact, std::abs(metered - m.exact), m.quantised, m.binned);
        EXPECT_NEAR(metered, m.binned, 1e-4 / ln2);
        EXPECT_NEAR(metered, m.exact, m.quantised + 1e-4 / ln2);
        EXPECT_LT(m.quantised, 0.25 * kEvPerBin) << "bin centres would be off by up to half a bin";
    }
}

TEST(ExposurePercentiles, OptionTakesLowBelowHighInsideZeroToHundred) {
    const OptionRow* row = lightingOptions().find("--exposure-percentiles");
    ASSERT_NE(row, nullptr);
    LightingSettings s;
    row->set(&s, "10,90.5");
    EXPECT_EQ(s.exposureLowPercentile, 10.0f);
    EXPECT_EQ(s.exposureHighPercentile, 90.5f);
    EXPECT_EQ(row->value(&s), "10,90.5");
    row->set(&s, "0,100");
    EXPECT_NO_THROW(validate(s));
    for (const char* bad :
         {"50", "50,", ",50", "a,b", "60,40", "50,50", "-1,50", "0,101", "10,90,95", "nan,90", "10 ,90"})
        EXPECT_THROW(row->set(&s, bad), std::invalid_argument) << bad;
    EXPECT_EQ(s.exposureLowPercentile, 0.0f) << "a refused value leaves the settings alone";
    s.exposureLowPercentile = 100.0f;
    EXPECT_THROW(validate(s), std::invalid_argument);
}

}  // namespace
}  // namespace penumbra::test
