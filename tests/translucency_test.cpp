// Camera translucency (src/dsm/translucency.h) on lavapipe with validation: k BLEND layers added in
// a random order composite to the exact over operator (double precision, closed-form Lambert
// radiance); a 50% quad in front of a lit wall shows 0.5 x quad + 0.5 x wall in the linear EXR,
// while the wall in the quad's deep shadow gets half the light; the BLEND row of the glTF sample
// AlphaBlendModeTest shows the surface behind it, each pixel a mix of the quad drawn opaque and the
// scene without it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <random>

#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "io/image_io.h"
#include "scene/builders.h"

using namespace penumbra;
using namespace penumbra::test;
namespace fs = std::filesystem;

namespace {

constexpr uint32_t kW = 48, kH = 48;

uint32_t addBlend(Scene& s, const glm::vec3& rgb, float alpha) {
    const uint32_t m = addMaterial(s, rgb);
    s.materials[m].alphaMode = AlphaMode::Blend;
    s.materials[m].baseColor.a = alpha;
    return m;
}

Camera frontCamera() {
    Camera c;
    c.eye = {0.0f, 0.0f, 10.0f};
    c.target = {0.0f, 0.0f, 0.0f};
    c.fovy = glm::radians(30.0f);
    return c;
}

// A directional light of irradiance `e` travelling along `dir`.
Light sun(const glm::vec3& dir, float e, bool shadow) {
    Light l;
    l.type = LightType::Directional;
    l.direction = glm::normalize(dir);
    l.intensity = e;
    l.castsShadow = shadow;
    return l;
}

struct Layer {
    glm::vec3 albedo;
    float alpha;
};

class TranslucencyTest : public GpuTest {
protected:
    FloatImage renderWith(const Scene& s, RenderSettings rs, const OitFrameStats** statsOut = nullptr) {
        rs.width = kW;
        rs.height = kH;
        TestRenderer r(ctx(), s, rs);
        r.render(frontCamera());
        EXPECT_NE(r.translucency(), nullptr);
        if (r.translucency()) stats_ = r.translucency()->readStats(r.commands());
        if (statsOut) *statsOut = &stats_;
        return {kW, kH, r.readHdr()};
    }
    OitFrameStats stats_;
};

}  // namespace

// 1.4 x 1.4 layers facing the camera at z = 1 + 0.05 j over an opaque wall at z = 0, lit head-on by an
// unshadowed sun of irradiance pi: every layer's radiance is its albedo. Added to the scene (and
// drawn) in a shuffled order, they must composite to sum_j T_j a_j rho_j + T_k L_wall, L_wall the
// opaque image's value (the wall's albedo quantized by the G-buffer's sRGB8 target).
TEST_F(TranslucencyTest, RandomOrderLayersEqualTheOverOperator) {
    const float pi = 3.14159265f;
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> sixteenth(1, 15);
    for (uint32_t k : {1u, 4u, 9u, 16u, 40u}) {
        std::vector<Layer> layers(k);
        for (Layer& l : layers)  // multiples of 1/16: exact in the nodes' half floats
            l.albedo = glm::vec3(sixteenth(rng), sixteenth(rng), sixteenth(rng)) / 16.0f, l.alpha = sixteenth(rng) / 16.0f;
        // Beyond OIT_MAX_LIST the farthest layers are merged into one with the last kept layer's
        // radiance: exact when they share it, which 40 layers of one colour test.
        if (k > OIT_MAX_LIST)
            for (Layer& l : layers) l.albedo = layers[0].albedo;
        std::vector<size_t> order(k);
        std::iota(order.begin(), order.end(), size_t(0));
        std::shuffle(order.begin(), order.end(), rng);
        Scene s;
        s.name = "oit-layers";
        for (size_t j : order)
            addQuad(s, {-0.7f, -0.7f, 1.0f + 0.05f * float(j)}, {1.4f, 0, 0}, {0, 1.4f, 0},
                    addBlend(s, layers[j].albedo, layers[j].alpha));
        const glm::vec3 wall(0.5f, 0.25f, 0.75f);
        addQuad(s, {-3.0f, -3.0f, 0.0f}, {6, 0, 0}, {0, 6, 0}, addMaterial(s, wall));
        s.lights.push_back(sun({0, 0, -1}, pi, false));
        s.computeBounds();
        const FloatImage img = renderWith(s, {});

        glm::dvec3 expected(0.0);
        double t = 1.0;
        for (int j = int(k) - 1; j >= 0; --j) {  // nearest (largest z) first
            expected += t * double(layers[j].alpha) * glm::dvec3(layers[j].albedo);
            t *= 1.0 - double(layers[j].alpha);
        }
        // The opaque image under the layers is the wall's radiance as the G-buffer path lit it (its
        // albedo went through the sRGB8 target): read where no layer covers it.
        const glm::dvec3 opaque(img.at(1, 1, 0), img.at(1, 1, 1), img.at(1, 1, 2));
        EXPECT_LT(glm::length(opaque - glm::dvec3(wall)), 6e-3);
        expected += t * opaque;
        double worst = 0.0;
        uint32_t pixels = 0;
        for (uint32_t y = kH / 2 - 6; y < kH / 2 + 6; ++y)
            for (uint32_t x = kW / 2 - 6; x < kW / 2 + 6; ++x, ++pixels)
                for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(double(img.at(x, y, c)) - expected[c]));
        std::printf("[oit layers] k=%u: expected (%.5f %.5f %.5f), max error %.2e over %u pixels; %llu fragments, "
                    "longest list %u\n",
                    k, expected.x, expected.y, expected.z, worst, pixels, (unsigned long long)stats_.fragments,
                    stats_.longest);
        EXPECT_LT(worst, 1e-3) << "k = " << k;
        EXPECT_EQ(stats_.longest, k);
        EXPECT_EQ(stats_.overflow, 0u);
        if (k > OIT_MAX_LIST) EXPECT_GE(stats_.beyondMaxList, uint64_t(k - OIT_MAX_LIST) * pixels);  // merged
        else EXPECT_EQ(stats_.beyondMaxList, 0u);
    }
}

// Pixels whose runs hold thousands of fragments: 2100 small layers within 0.05 of one another near
// the camera, all in the nearest depth bucket and so all stored, in a shuffled order, each its own
// colour and alpha. The 32 nearest must be composited exactly in order and the rest merged behind
// them (their combined alpha, the 32nd's radiance), as in a run of a few layers.
TEST_F(TranslucencyTest, LongRunsKeepTheNearestInOrder) {
    constexpr uint32_t k = 2100;
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> sixteenth(1, 15);
    std::vector<Layer> layers(k);
    for (Layer& l : layers)
        l.albedo = glm::vec3(sixteenth(rng), sixteenth(rng), sixteenth(rng)) / 16.0f, l.alpha = sixteenth(rng) / 16.0f;
    std::vector<size_t> order(k);
    std::iota(order.begin(), order.end(), size_t(0));
    std::shuffle(order.begin(), order.end(), rng);
    Scene s;
    s.name = "oit-long-run";
    for (size_t j : order)  // layer j at distance 1.5 + 0.05 j / k from the eye: j = 0 nearest
        addQuad(s, {-0.02f, -0.02f, 8.5f - 0.05f * float(j) / float(k)}, {0.04f, 0, 0}, {0, 0.04f, 0},
                addBlend(s, layers[j].albedo, layers[j].alpha));
    addQuad(s, {-3.0f, -3.0f, 0.0f}, {6, 0, 0}, {0, 6, 0}, addMaterial(s, glm::vec3(0.5f, 0.25f, 0.75f)));
    s.lights.push_back(sun({0, 0, -1}, 3.14159265f, false));
    s.computeBounds();
    const FloatImage img = renderWith(s, {});

    glm::dvec3 expected(0.0);
    double t = 1.0;
    for (uint32_t j = 0; j < OIT_MAX_LIST; ++j) {
        expected += t * double(layers[j].alpha) * glm::dvec3(layers[j].albedo);
        t *= 1.0 - double(layers[j].alpha);
    }
    double tail = 1.0;  // the rest: about (1 - 1/2)^2068 on average, no light of the wall left
    for (uint32_t j = OIT_MAX_LIST; j < k; ++j) tail *= 1.0 - double(layers[j].alpha);
    expected += t * (1.0 - tail) * glm::dvec3(layers[OIT_MAX_LIST - 1].albedo);
    double worst = 0.0;
    for (uint32_t y = kH / 2 - 1; y <= kH / 2; ++y)
        for (uint32_t x = kW / 2 - 1; x <= kW / 2; ++x)
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(double(img.at(x, y, c)) - expected[c]));
    const uint64_t stored = stats_.fragments - stats_.leftOut;
    std::printf("[oit long run] %u layers: expected (%.5f %.5f %.5f), max error %.2e over the 4 centre pixels; %llu "
                "fragments, %llu stored, longest list %u\n",
                k, expected.x, expected.y, expected.z, worst, (unsigned long long)stats_.fragments,
                (unsigned long long)stored, stats_.longest);
    EXPECT_EQ(stats_.overflow, 0u);
    EXPECT_EQ(stats_.longest, k);
    EXPECT_GE(stored, 4u * k);  // the centre pixels' whole runs were stored
    EXPECT_LT(worst, 1e-3);
}

// A 2 x 2 quad of alpha 0.5 at z = 1 over a wall at z = 0, a sun at 36.9 degrees (n.l = 0.8) whose
// deep shadow map takes the quad: through the quad (left, away from its shadow, which falls to the
// right) the EXR holds 0.5 quad + 0.5 wall (the lit wall as the opaque image holds it); the wall in
// the quad's deep shadow and outside the quad's image gets half of that.
TEST_F(TranslucencyTest, HalfTransparentQuadOverLitWall) {
    const float pi = 3.14159265f;
    Scene s;
    s.name = "oit-quad";
    const glm::vec3 quad(0.8f, 0.4f, 0.2f), wall(0.3f, 0.6f, 0.9f);
    addQuad(s, {-1.0f, -1.0f, 1.0f}, {2, 0, 0}, {0, 2, 0}, addBlend(s, quad, 0.5f));
    addQuad(s, {-3.0f, -3.0f, 0.0f}, {6, 0, 0}, {0, 6, 0}, addMaterial(s, wall));
    s.lights.push_back(sun({0.6f, 0.0f, -0.8f}, pi, true));
    s.computeBounds();
    RenderSettings rs;
    rs.shadow.resolution = 256;
    rs.dsm.enabled = true;
    const FloatImage hdr = renderWith(s, rs);
    const fs::path exr = fs::temp_directory_path() / "penumbra-oit-quad.exr";
    writeExr(exr.string(), hdr.width, hdr.height, hdr.rgba);
    const ImageF img = readExr(exr.string());
    fs::remove(exr);
    auto at = [&](uint32_t x, uint32_t y, int c) { return double(img.rgba[(size_t(y) * img.width + x) * 4 + c]); };

    // The lit wall as the opaque path renders it (albedo through the G-buffer's sRGB8 target), read
    // at the image corner: n.l = 0.8, irradiance pi.
    const glm::dvec3 litWall(at(1, 1, 0), at(1, 1, 1), at(1, 1, 2));
    EXPECT_LT(glm::length(litWall - 0.8 * glm::dvec3(wall)), 6e-3);
    const Camera cam = frontCamera();
    double worstThrough = 0.0, worstShadow = 0.0;
    uint32_t through = 0, shadowed = 0;
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x) {
            const Ray r = cameraRay(cam, kW, kH, x, y);
            const dvec3 q = r.origin + r.dir * ((1.0 - r.origin.z) / r.dir.z);  // on the quad's plane
            const dvec3 w = r.origin + r.dir * ((0.0 - r.origin.z) / r.dir.z);  // on the wall
            const bool inQuad = std::abs(q.x) < 0.9 && std::abs(q.y) < 0.9;
            // The quad's shadow on the wall: x in [-0.25, 1.75] (shifted by 0.75), |y| < 1.
            if (inQuad && w.x < -0.5) {  // seen through the quad, the wall there is lit
                ++through;
                for (int c = 0; c < 3; ++c)
                    worstThrough = std::max(worstThrough, std::abs(at(x, y, c) - (0.5 * 0.8 * quad[c] + 0.5 * litWall[c])));
            } else if (!inQuad && std::abs(q.x) > 1.1 && w.x > 0.3 && w.x < 1.5 && std::abs(w.y) < 0.8) {
                ++shadowed;
                for (int c = 0; c < 3; ++c)
                    worstShadow = std::max(worstShadow, std::abs(at(x, y, c) - 0.5 * litWall[c]));
            }
        }
    std::printf("[oit quad] through the quad: max error %.2e over %u pixels; in its deep shadow: %.2e over %u\n",
                worstThrough, through, worstShadow, shadowed);
    ASSERT_GT(through, 20u);
    ASSERT_GT(shadowed, 10u);
    EXPECT_LT(worstThrough, 1e-3);
    EXPECT_LT(worstShadow, 1e-3);
}

// AlphaBlendModeTest with its default camera and lights: where the BLEND row's surfaces are seen
// (the image with them drawn opaque differs from the image without them), the translucent image
// is, channel by channel, the same mix a x opaque + (1 - a) x behind, with a in [0, 1] and well
// below 1 on average (the row's texture fades to transparent).
TEST_F(TranslucencyTest, AlphaBlendModeTestShowsWhatIsBehind) {
    const fs::path path = fs::path(PENUMBRA_SOURCE_DIR) / ".." / "shared" / "assets" / "AlphaBlendModeTest" /
                          "glTF" / "AlphaBlendModeTest.gltf";
    if (!fs::exists(path)) GTEST_SKIP() << "no ../shared/assets";
    const Scene scene = loadScene(path.string());
    Scene without = scene;
    for (Material& m : without.materials)
        if (m.alphaMode == AlphaMode::Blend) m.baseColor.a = 0.0f;  // nothing of them is composited
    auto draw = [&](const Scene& s, bool translucency) {
        RenderSettings rs;
        rs.width = 128;
        rs.height = 96;
        rs.translucency = translucency;
        TestRenderer r(ctx(), s, rs);
        r.render(s.cameras.at(0));
        return FloatImage{128, 96, r.readHdr()};
    };
    const FloatImage on = draw(scene, true), opaque = draw(scene, false), behind = draw(without, true);
    uint32_t seen = 0;
    double sumA = 0.0, worst = 0.0;
    for (uint32_t y = 0; y < 96; ++y)
        for (uint32_t x = 0; x < 128; ++x) {
            int best = 0;  // the channel where the surface and what is behind differ most
            for (int c = 1; c < 3; ++c)
                if (std::abs(opaque.at(x, y, c) - behind.at(x, y, c)) > std::abs(opaque.at(x, y, best) - behind.at(x, y, best)))
                    best = c;
            const double d = double(opaque.at(x, y, best)) - behind.at(x, y, best);
            if (std::abs(d) < 0.05) continue;
            ++seen;
            const double a = (double(on.at(x, y, best)) - behind.at(x, y, best)) / d;
            sumA += a;
            EXPECT_GE(a, -0.01) << x << "," << y;
            EXPECT_LE(a, 1.01) << x << "," << y;
            for (int c = 0; c < 3; ++c) {
                const double mix = a * opaque.at(x, y, c) + (1.0 - a) * behind.at(x, y, c);
                worst = std::max(worst, std::abs(on.at(x, y, c) - mix) / std::max(0.05, double(std::abs(d))));
            }
        }
    std::printf("[oit AlphaBlendModeTest] %u pixels show a BLEND surface; mean alpha %.3f; largest channel "
                "mismatch %.3f of the surface/behind contrast\n",
                seen, seen ? sumA / seen : 0.0, worst);
    ASSERT_GT(seen, 50u);
    EXPECT_LT(sumA / seen, 0.8);
    EXPECT_LT(worst, 0.02);
}
