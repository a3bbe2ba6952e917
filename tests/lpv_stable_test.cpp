// An LPV that holds still: injection sums in fixed point give the same volume bits in any order (and
// the exact sum to float precision), a still view gives the same volume frame after frame and from a
// second renderer, and a camera move inside a cell leaves the volume's bits as they were.
#include <algorithm>
#include <cmath>
#include <random>

#include "lpv_volume.h"
#include "scene/builders.h"

namespace penumbra::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

glm::dvec4 cosineLobe(const dvec3& n) {
    const double c1 = std::sqrt(kPi / 3.0);
    return {std::sqrt(kPi) / 2.0, -c1 * n.y, c1 * n.z, -c1 * n.x};
}
const double kLobePeak = std::sqrt(kPi) / 2.0 * 0.282094792 + std::sqrt(kPi / 3.0) * 0.488602512;

bool awayFromEdges(const dvec3& g, double margin) {
    const dvec3 f = g - glm::floor(g);
    return glm::all(glm::greaterThan(f, dvec3(margin))) && glm::all(glm::lessThan(f, dvec3(1.0 - margin)));
}

std::vector<uint8_t> bytesOf(TestRenderer& r, const vk::Buffer& b) { return r.commands().readBuffer(b, b.size()); }

}  // namespace

// 3000 VPLs crowded around 12 cells of a 16^3 grid, their flux spread over six decades, injected in
// two orders: the light and geometry volumes are the same bits. Each coefficient against the sum of
// the same contributions in double precision: the light within 1e-6 of the sum of the weighted
// contributions' magnitudes (each float contribution carries a few roundings of 2^-24) plus 4e-6 of
// the unweighted ones' (a float splat weight is off by a few ulps of the grid coordinate, 2^-20
// here), and each colour's total within 1e-6; the geometry (nearest corner, placed at least 0.02
// cell from a corner's border; a fixed scale of 2^28: 2^-29 per surfel) within 1e-6 of its
// magnitudes plus 2^-29 per surfel.
TEST_F(LpvVolumeTest, InjectionSumsAreTheSameBitsInAnyOrderAndExactToFloatPrecision) {
    constexpr uint32_t kRes = 16;
    const float cell = 2.04f / float(kRes - 1);
    const dvec3 origin = dvec3(-1.02 - 0.5 * cell);  // placeCascades' fit of the unit cube
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<glm::ivec3> crowded;
    for (int i = 0; i < 12; ++i)
        crowded.push_back(glm::ivec3(1 + int(u(rng) * 13), 1 + int(u(rng) * 13), 1 + int(u(rng) * 13)));
    const size_t cells = size_t(kRes) * kRes * kRes;
    struct Sum {
        glm::dvec4 value{0.0}, weighted{0.0}, unweighted{0.0};  // the sum, of |w c|, of |c|
        int count = 0;
    };
    std::vector<Sum> light(3 * cells), geometry(cells);
    glm::dvec4 total[3] = {}, totalSize[3] = {};
    auto index = [&](glm::ivec3 c) { return (size_t(c.z) * kRes + c.y) * kRes + c.x; };
    std::vector<gpu::GpuVpl> vpls;
    while (vpls.size() < 3000) {
        const glm::vec3 n = glm::normalize(glm::vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5) + glm::vec3(1e-3f));
        const glm::ivec3 target = crowded[vpls.size() % crowded.size()];
        const dvec3 t = origin + (dvec3(target) + dvec3(0.15 + 0.7 * u(rng), 0.15 + 0.7 * u(rng), 0.15 + 0.7 * u(rng))) * double(cell);
        const glm::vec3 p = glm::vec3(t - 0.5 * double(cell) * dvec3(n));
        const dvec3 corner = (dvec3(p) - origin) / double(cell) + 0.5;
        if (!awayFromEdges(corner, 0.02)) continue;
        const glm::vec3 flux(std::pow(10.0, 6.0 * u(rng) - 3.0), std::pow(10.0, 6.0 * u(rng) - 3.0),
                             std::pow(10.0, 6.0 * u(rng) - 3.0));
        const float area = float(u(rng)) * cell * cell;
        vpls.push_back(vpl(p, n, flux, area));
        const glm::dvec4 lobe = cosineLobe(dvec3(vpls.back().normal));
        const dvec3 g = (dvec3(p) + 0.5 * double(cell) * dvec3(vpls.back().normal) - origin) / double(cell) - 0.5;
        const dvec3 f = g - glm::floor(g);
        for (int i = 0; i < 8; ++i) {
            const glm::ivec3 o(i & 1, (i >> 1) & 1, i >> 2);
            const dvec3 w3 = glm::mix(1.0 - f, f, dvec3(o));
            const double w = w3.x * w3.y * w3.z;
            for (int ch = 0; ch < 3; ++ch) {
                const glm::dvec4 c = lobe * (double(flux[ch]) / kPi);
                Sum& sum = light[ch * cells + index(glm::ivec3(glm::floor(g)) + o)];
                sum.value += w * c;
                sum.weighted += w * glm::abs(c);
                sum.unweighted += glm::abs(c);
                total[ch] += w * c;
                totalSize[ch] += w * glm::abs(c);
            }
        }
        const glm::dvec4 blocking = lobe * (std::min(double(area) / (double(cell) * cell), 1.0) / kLobePeak);
        Sum& sum = geometry[index(glm::ivec3(glm::floor(corner)))];
        sum.value += blocking;
        sum.weighted += glm::abs(blocking);
        ++sum.count;
    }
    const VolumeRun a = run(vpls, 1, true, kRes);
    std::shuffle(vpls.begin(), vpls.end(), rng);
    const VolumeRun b = run(vpls, 1, true, kRes);
    ASSERT_EQ(a.injected.size(), light.size());
    EXPECT_EQ(std::memcmp(a.injected.data(), b.injected.data(), a.injected.size() * sizeof(glm::vec4)), 0);
    EXPECT_EQ(std::memcmp(a.geometry.data(), b.geometry.data(), a.geometry.size() * sizeof(glm::vec4)), 0);
    EXPECT_EQ(std::memcmp(a.accum.data(), b.accum.data(), a.accum.size() * sizeof(glm::vec4)), 0);
    double worstLight = 0.0, worstGeometry = 0.0, worstTotal = 0.0;
    size_t filled = 0;
    glm::dvec4 gpuTotal[3] = {};
    for (size_t i = 0; i < light.size(); ++i)
        for (int k = 0; k < 4; ++k) {
            const Sum& sum = light[i];
            filled += sum.weighted[k] > 0.0;
            gpuTotal[i / cells][k] += a.injected[i][k];
            const double bound = 1e-6 * sum.weighted[k] + 4e-6 * sum.unweighted[k];
            worstLight = std::max(worstLight, std::abs(double(a.injected[i][k]) - sum.value[k]) / std::max(bound, 1e-30));
        }
    for (int ch = 0; ch < 3; ++ch)
        for (int k = 0; k < 4; ++k)
            worstTotal = std::max(worstTotal, std::abs(gpuTotal[ch][k] - total[ch][k]) / totalSize[ch][k]);
    for (size_t i = 0; i < geometry.size(); ++i)
        for (int k = 0; k < 4; ++k) {
            const Sum& sum = geometry[i];
            const double bound = 1e-6 * sum.weighted[k] + std::ldexp(double(sum.count), -29);
            worstGeometry = std::max(worstGeometry, std::abs(double(a.geometry[i][k]) - sum.value[k]) / std::max(bound, 1e-30));
        }
    std::printf("[ lpv fixed point ] %zu coefficients filled; largest error over its bound: light %.3f, geometry %.3f; "
                "colour totals within %.2e\n", filled, worstLight, worstGeometry, worstTotal);
    EXPECT_GE(filled, 12u * 3u * 4u * 8u);
    EXPECT_LT(worstLight, 1.0);
    EXPECT_LT(worstGeometry, 1.0);
    EXPECT_LT(worstTotal, 1e-6);
}

// A still light and camera: cornell's volumes and indirect image are the same bits in every frame,
// and a second renderer gives the same bits again.
TEST_F(GpuTest, LpvStillViewGivesTheSameBitsEveryFrame) {
    const Scene scene = makeBuiltinScene("cornell");
    RenderSettings s;
    s.width = 96;
    s.height = 72;
    s.gi = GiMode::Lpv;
    s.giTemporal = false;
    s.aov = Aov::Indirect;
    s.lpv.rsmResolution = 256;
    s.lpv.vplResolution = 64;
    struct Frame {
        std::vector<uint8_t> accum, geometry;
        std::vector<float> image;
    };
    std::vector<Frame> frames;
    for (int renderer = 0; renderer < 2; ++renderer) {
        TestRenderer r(ctx(), scene, s);
        for (int frame = 0; frame < (renderer == 0 ? 4 : 1); ++frame) {
            r.render(scene.cameras[0]);
            frames.push_back({bytesOf(r, r.lpv()->accumulated()), bytesOf(r, r.lpv()->geometry()), r.readHdr()});
        }
    }
    double mean = 0.0;
    for (size_t i = 0; i < frames[0].image.size(); i += 4) mean += frames[0].image[i + 1];
    EXPECT_GT(mean, 0.0);
    for (size_t f = 1; f < frames.size(); ++f) {
        const char* which = f + 1 < frames.size() ? "a later frame" : "a second renderer";
        EXPECT_EQ(frames[f].accum, frames[0].accum) << which << ", frame " << f;
        EXPECT_EQ(frames[f].geometry, frames[0].geometry) << which << ", frame " << f;
        EXPECT_EQ(frames[f].image, frames[0].image) << which << ", frame " << f;
    }
}

// A camera move inside the finest cell keeps every cascade where it was (origins snap to whole cells),
// and the spot light's RSM does not depend on the camera: without camera-injected occluders the
// volumes are the same bits. Cornell with bounds widened past the 20 m under which grids are fit to
// the scene, so that they are nested around the eye. Camera surfels (the default) are what the
// camera sees, so they change with it: printed.
TEST_F(GpuTest, LpvCameraMoveInsideACellKeepsTheVolumeBits) {
    Scene scene = makeBuiltinScene("cornell");
    const glm::vec3 centre = scene.bounds.center();
    scene.bounds.extend(centre + glm::vec3(12.0f));
    scene.bounds.extend(centre - glm::vec3(12.0f));
    RenderSettings s;
    s.width = 64;
    s.height = 48;
    s.gi = GiMode::Lpv;
    s.giTemporal = false;
    s.lpv.cascades = 3;
    s.lpv.rsmResolution = 256;
    s.lpv.vplResolution = 64;
    const Camera a = scene.cameras[0];
    const auto grids = placeCascades(scene.bounds, a.eye, 3, s.lpv.resolution);
    // Towards the centre of the finest cell holding the eye, by 0.3 cell along each axis at most.
    const float cell = grids[0].cellSize;
    const glm::vec3 inCell = (a.eye - glm::vec3(grids[0].origin)) / cell;
    const glm::vec3 move = glm::clamp(glm::floor(inCell) + 0.5f - inCell, -0.3f, 0.3f) * cell;
    Camera b = a;
    b.eye += move;
    b.target += move;
    ASSERT_GT(glm::length(move), 0.1f * cell);
    const auto moved = placeCascades(scene.bounds, b.eye, 3, s.lpv.resolution);
    for (size_t k = 0; k < grids.size(); ++k) ASSERT_EQ(grids[k].origin, moved[k].origin) << "cascade " << k;
    for (bool cameraGeometry : {false, true}) {
        s.lpv.cameraGeometry = cameraGeometry;
        TestRenderer r(ctx(), scene, s);
        r.render(a);
        const std::vector<glm::vec4> before = asVec4(bytesOf(r, r.lpv()->accumulated()));
        r.render(b);
        const std::vector<glm::vec4> after = asVec4(bytesOf(r, r.lpv()->accumulated()));
        ASSERT_EQ(before.size(), after.size());
        size_t differ = 0, lit = 0;
        for (size_t i = 0; i < before.size(); ++i) {
            differ += std::memcmp(&before[i], &after[i], sizeof(glm::vec4)) != 0;
            lit += before[i].x > 0.0f;
        }
        std::printf("[ lpv camera move ] %.3f m inside a %.3f m cell, camera geometry %s: %zu of %zu cell colours "
                    "changed\n", glm::length(move), cell, cameraGeometry ? "on" : "off", differ, before.size());
        EXPECT_GT(lit, 100u);
        if (!cameraGeometry) {
            EXPECT_EQ(differ, 0u);
        }
    }
}

}  // namespace penumbra::test
