// Deep shadow maps on lavapipe with validation (gpu_fixture.h): transmittance through stacked
// translucent layers against the closed form (1 - alpha)^k, independent of the drawing order; the
// per-texel cap keeps the nearest nodes; pool overflow is counted and reported with a finite image;
// the resolved lists and neighbour links of the hair scene satisfy their invariants; hair under a
// deep shadow map gets partial (soft) shadows where an ordinary shadow map gives binary ones.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "scene/builders.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

constexpr uint32_t kW = 64, kH = 64;
constexpr float kCeilingY = 3.0f, kFloorY = 0.5f;

struct DsmRun {
    FloatImage image;
    DsmFrameStats stats;
    std::vector<std::string> warnings;
};

// A translucent, single-sided material (alphaMode BLEND) with opacity `alpha`.
uint32_t addBlendMaterial(Scene& s, float alpha) {
    const uint32_t m = addMaterial(s, glm::vec3(0.8f));
    s.materials[m].alphaMode = AlphaMode::Blend;
    s.materials[m].baseColor.a = alpha;
    return m;
}

// Layers j = 0..n-1 at y = 1 + spacing j, 4 x 4, facing down towards a directional light that shines
// up: the light sees their fronts, the camera above their backs (culled: the camera sees through
// them). Opaque receivers above every layer (x > 0) and below every layer (x < 0).
// Layer j has opacity alphas[j] and is added in the order `order` (which the GPU draws in).
Scene stackedLayers(const std::vector<float>& alphas, const std::vector<size_t>& order, float spacing = 0.1f) {
    Scene s;
    s.name = "dsm-layers";
    std::vector<uint32_t> materials;
    for (float a : alphas) materials.push_back(addBlendMaterial(s, a));
    for (size_t j : order)
        addQuad(s, {-2.0f, 1.0f + spacing * float(j), -2.0f}, {4, 0, 0}, {0, 0, 4}, materials[j]);  // normal -y
    const uint32_t grey = addMaterial(s, glm::vec3(0.5f));
    addQuad(s, {0.2f, kCeilingY, -1.5f}, {0, 0, 3}, {1.3f, 0, 0}, grey);   // above the layers, facing up
    addQuad(s, {-1.5f, kFloorY, -1.5f}, {0, 0, 3}, {1.3f, 0, 0}, grey);    // below them, facing up
    Light up;
    up.type = LightType::Directional;
    up.direction = {0.0f, 1.0f, 0.0f};
    up.name = "from below";
    s.lights.push_back(up);
    s.computeBounds();
    return s;
}

Camera topCamera() {
    Camera c;
    c.eye = {0.0f, 10.0f, 0.0f};
    c.target = {0.0f, 0.0f, 0.0f};
    c.up = {0.0f, 0.0f, -1.0f};
    c.fovy = glm::radians(30.0f);
    return c;
}

std::vector<size_t> shuffled(size_t n, uint32_t seed) {
    std::vector<size_t> order(n);
    std::iota(order.begin(), order.end(), size_t(0));
    std::mt19937 rng(seed);
    std::shuffle(order.begin(), order.end(), rng);
    return order;
}

// The pixels that see receiver `y` (a plate of the stackedLayers scene) at least `margin` inside it.
std::vector<std::pair<uint32_t, uint32_t>> platePixels(float y, bool above, double margin = 0.15) {
    const Camera cam = topCamera();
    std::vector<std::pair<uint32_t, uint32_t>> out;
    for (uint32_t py = 0; py < kH; ++py)
        for (uint32_t px = 0; px < kW; ++px) {
            const Ray r = cameraRay(cam, kW, kH, px, py);
            const std::optional<double> t = hitHorizontalPlane(r, y);
            if (!t) continue;
            const dvec3 p = r.origin + *t * r.dir;
            const double x0 = above ? 0.2 : -1.5;
            if (p.x > x0 + margin && p.x < x0 + 1.3 - margin && std::abs(p.z) < 1.5 - margin) out.push_back({px, py});
        }
    return out;
}

class DsmTest : public GpuTest {
protected:
    DsmRun renderDsm(const Scene& scene, const Camera& cam, uint32_t w, uint32_t h, Aov aov, DsmSettings dsm,
                     uint32_t shadowRes = 64) {
        RenderSettings rs;
        rs.width = w;
        rs.height = h;
        rs.aov = aov;
        rs.shadow.resolution = shadowRes;
        dsm.enabled = true;
        rs.dsm = dsm;
        TestRenderer r(ctx(), scene, rs);
        r.render(cam);
        DsmRun out{{w, h, r.readHdr()}, r.deepShadows().readStats(r.commands()), r.warnings()};
        const std::vector<std::string> frame = dsmWarnings(out.stats);
        out.warnings.insert(out.warnings.end(), frame.begin(), frame.end());
        return out;
    }

    // Largest |T - expected| over the pixels, reported and returned.
    static double maxError(const FloatImage& img, const std::vector<std::pair<uint32_t, uint32_t>>& pixels,
                           double expected) {
        double worst = 0.0;
        for (auto [x, y] : pixels) worst = std::max(worst, std::abs(double(img.at(x, y)) - expected));
        return worst;
    }
};

}  // namespace

// k = 1..8 layers of opacity 0.3, each k in its own shuffled drawing order: behind all k layers the
// transmittance is (1 - 0.3)^k, in front of them 1.
TEST_F(DsmTest, StackedLayersGiveClosedFormTransmittance) {
    constexpr float kAlpha = 0.3f;
    const auto above = platePixels(kCeilingY, true), below = platePixels(kFloorY, false);
    ASSERT_GT(above.size(), 100u);
    ASSERT_GT(below.size(), 100u);
    for (uint32_t k = 1; k <= 8; ++k) {
        const Scene s = stackedLayers(std::vector<float>(k, kAlpha), shuffled(k, 100 + k));
        const DsmRun run = renderDsm(s, topCamera(), kW, kH, Aov::Transmittance, {});
        const double expected = std::pow(1.0 - double(kAlpha), double(k));
        const double errBehind = maxError(run.image, above, expected), errFront = maxError(run.image, below, 1.0);
        std::printf("[dsm layers] k=%u: T behind = %.6f (expected %.6f), max error %.2e; in front max error %.2e; "
                    "%llu fragments, longest list %u\n",
                    k, double(run.image.at(above[0].first, above[0].second)), expected, errBehind, errFront,
                    (unsigned long long)run.stats.fragments, run.stats.longest);
        EXPECT_LT(errBehind, 1e-3) << "k = " << k;
        EXPECT_LT(errFront, 1e-6) << "k = " << k;
        EXPECT_EQ(run.stats.longest, k);
        EXPECT_EQ(run.stats.overflow, 0u);
    }
}

// The same 8 layers with different opacities, drawn in two different orders: identical images.
TEST_F(DsmTest, DrawingOrderDoesNotMatter) {
    const std::vector<float> alphas{0.1f, 0.5f, 0.2f, 0.7f, 0.3f, 0.05f, 0.6f, 0.25f};
    double expected = 1.0;
    for (float a : alphas) expected *= 1.0 - double(a);
    const DsmRun a = renderDsm(stackedLayers(alphas, shuffled(8, 1)), topCamera(), kW, kH, Aov::Transmittance, {});
    const DsmRun b = renderDsm(stackedLayers(alphas, shuffled(8, 2)), topCamera(), kW, kH, Aov::Transmittance, {});
    double diff = 0.0;
    for (size_t i = 0; i < a.image.rgba.size(); ++i)
        diff = std::max(diff, double(std::abs(a.image.rgba[i] - b.image.rgba[i])));
    const double err = maxError(a.image, platePixels(kCeilingY, true), expected);
    std::printf("[dsm order] two shuffles differ by at most %.2e; behind all layers error %.2e (T = %.6f)\n", diff,
                err, expected);
    EXPECT_LT(diff, 1e-6);
    EXPECT_LT(err, 1e-3);
}

// --dsm-max-list 3 with 8 layers: the 3 nearest the light are kept, so the transmittance behind all
// of them is the product over the first 3 opacities (not over the last 3), and the rest is counted.
TEST_F(DsmTest, ListCapKeepsNearestNodes) {
    const std::vector<float> alphas{0.1f, 0.15f, 0.2f, 0.25f, 0.3f, 0.35f, 0.4f, 0.45f};
    DsmSettings dsm;
    dsm.maxList = 3;
    const DsmRun run = renderDsm(stackedLayers(alphas, shuffled(8, 7)), topCamera(), kW, kH, Aov::Transmittance, dsm);
    const double nearest = (1 - 0.1) * (1 - 0.15) * (1 - 0.2), farthest = (1 - 0.35) * (1 - 0.4) * (1 - 0.45);
    const double err = maxError(run.image, platePixels(kCeilingY, true), nearest);
    std::printf("[dsm cap] T = %.6f (nearest three %.6f, farthest three %.6f), max error %.2e; %llu lists, %llu "
                "nodes kept, %llu beyond the cap\n",
                double(run.image.at(platePixels(kCeilingY, true)[0].first, platePixels(kCeilingY, true)[0].second)),
                nearest, farthest, err, (unsigned long long)run.stats.lists, (unsigned long long)run.stats.kept,
                (unsigned long long)run.stats.beyondMaxList);
    EXPECT_LT(err, 1e-3);
    EXPECT_EQ(run.stats.longest, 8u);
    EXPECT_GT(run.stats.lists, 0u);
    EXPECT_EQ(run.stats.kept, 3 * run.stats.lists);
    EXPECT_EQ(run.stats.beyondMaxList, 5 * run.stats.lists);
}

// k horizontal strands wide enough to cover the receivers (a 4 m ribbon has coverage 1: alpha =
// opacity), stacked like the layers above: behind all of them both volumetric techniques give the
// closed form (1 - 0.3)^k exactly (the opacity map's optical depths add up to -ln T whatever layers
// they fall in), in front of them 1. Between strands the deep opacity map interpolates within its
// layers where the lists are exact: that difference is what `eval --hair` measures.
// 300 layers in one texel, drawn in a shuffled order: more nodes than the resolve's shared slots
// (2 x DSM_MAX_LIST_CAP), so they come in batches, and after the first sort only nodes nearer than
// the farthest kept take a slot. Behind all of them the transmittance is the product over the cap's
// nearest layers (by depth from the light, not by drawing order), for the default cap and the largest.
TEST_F(DsmTest, LongListsKeepTheNearestNodesAcrossBatches) {
    constexpr size_t kLayers = 300;
    std::vector<float> alphas(kLayers);
    for (size_t j = 0; j < kLayers; ++j) alphas[j] = 0.01f + 0.04f * float(j) / kLayers + 0.002f * float((j * 37) % 11);
    const Scene s = stackedLayers(alphas, shuffled(kLayers, 11), 0.005f);
    for (uint32_t cap : {50u, uint32_t(DSM_MAX_LIST_CAP)}) {
        DsmSettings dsm;
        dsm.maxList = cap;
        dsm.poolNodes = 1 << 20;  // every fragment (1764 texels x 300) and the sorted lists
        const DsmRun run = renderDsm(s, topCamera(), kW, kH, Aov::Transmittance, dsm);
        EXPECT_EQ(run.stats.overflow, 0u);
        double nearest = 1.0, farthest = 1.0;
        for (size_t j = 0; j < cap; ++j) nearest *= 1.0 - double(alphas[j]), farthest *= 1.0 - double(alphas[kLayers - 1 - j]);
        const double err = maxError(run.image, platePixels(kCeilingY, true), nearest);
        std::printf("[dsm long lists] cap %u: T = %.6f against the nearest %u layers' %.6f (farthest %u: %.6f), max "
                    "error %.2e\n", cap, double(run.image.at(platePixels(kCeilingY, true)[0].first,
                                                             platePixels(kCeilingY, true)[0].second)),
                    cap, nearest, cap, farthest, err);
        EXPECT_LT(err, 1e-3) << "cap " << cap;
        EXPECT_EQ(run.stats.longest, kLayers);
        EXPECT_GT(run.stats.lists, 0u);
        EXPECT_EQ(run.stats.kept, cap * run.stats.lists);
        EXPECT_EQ(run.stats.beyondMaxList, (kLayers - cap) * run.stats.lists);
        // The depth buckets behind the cap's left nodes out of the sort (the layers span about half the
        // buckets' range: the scene has BLEND meshes, so the range is the scene's).
        std::printf("[dsm long lists] cap %u: %llu of %llu nodes sorted\n", cap, (unsigned long long)run.stats.sorted,
                    (unsigned long long)(kLayers * run.stats.lists));
        EXPECT_GE(run.stats.sorted, cap * run.stats.lists);
        if (cap == 50u) {
            EXPECT_LT(run.stats.sorted, kLayers / 2 * run.stats.lists);
        }
    }
}

TEST_F(DsmTest, StackedStrandsGiveClosedFormTransmittanceInBothTechniques) {
    constexpr float kAlpha = 0.3f;
    const auto above = platePixels(kCeilingY, true), below = platePixels(kFloorY, false);
    for (bool opacityMaps : {false, true})
        for (uint32_t k : {1u, 4u}) {
            Scene s = stackedLayers({}, {});
            Strand style;
            style.width = 4.0f;
            style.opacity = kAlpha;
            for (uint32_t j = 0; j < k; ++j) {
                const float y = 1.0f + 0.1f * float(j);
                const std::vector<glm::vec3> points{{-2.0f, y, 0.0f}, {0.0f, y, 0.0f}, {2.0f, y, 0.0f}};
                addStrand(s, points, style);
            }
            s.computeBounds();
            DsmSettings dsm;
            dsm.opacityMaps = opacityMaps;
            const DsmRun run = renderDsm(s, topCamera(), kW, kH, Aov::Transmittance, dsm);
            const double expected = std::pow(1.0 - double(kAlpha), double(k));
            const double errBehind = maxError(run.image, above, expected), errFront = maxError(run.image, below, 1.0);
            std::printf("[dsm strands] %s, k=%u: T behind max error %.2e (expected %.6f), in front %.2e\n",
                        opacityMaps ? "deep opacity map" : "deep shadow map", k, errBehind, expected, errFront);
            EXPECT_LT(errBehind, 1e-3) << k;
            EXPECT_LT(errFront, 1e-6) << k;
        }
}

// A point light's deep shadow map is a cube of six faces. k nested translucent cubes (opacity 0.3)
// around the light, inside an opaque room: every ray from the light to a wall crosses each cube
// once, so the walls' transmittance is (1 - 0.3)^k in every direction. Two cameras at the light,
// looking along +(1,1,1) and -(1,1,1), see all six walls; pixels near the cube's edges, where a
// ray grazes two faces of a layer (and where the DSM's faces meet), are left out.
TEST_F(DsmTest, NestedLayersAroundAPointLightGiveClosedFormTransmittance) {
    constexpr float kAlpha = 0.3f, kRoom = 2.0f;
    constexpr uint32_t kSize = 48;
    auto addCube = [](Scene& s, float half, uint32_t material) {
        for (int axis = 0; axis < 3; ++axis)
            for (float sign : {-1.0f, 1.0f}) {
                glm::vec3 n(0.0f), u(0.0f), v(0.0f);
                n[axis] = sign * half;
                u[(axis + 1) % 3] = 2.0f * half;
                v[(axis + 2) % 3] = 2.0f * half;
                addQuad(s, n - 0.5f * u - 0.5f * v, u, v, material);
            }
    };
    for (uint32_t k : {1u, 3u}) {
        Scene s;
        s.name = "dsm-point";
        const uint32_t layer = addBlendMaterial(s, kAlpha), wall = addMaterial(s, glm::vec3(0.5f));
        s.materials[layer].doubleSided = true;
        s.materials[wall].doubleSided = true;
        for (uint32_t j = 0; j < k; ++j) addCube(s, 0.4f + 0.2f * float(j), layer);
        addCube(s, kRoom, wall);
        Light point;
        point.type = LightType::Point;
        point.position = glm::vec3(0.0f);
        s.lights.push_back(point);
        s.computeBounds();
        const double expected = std::pow(1.0 - double(kAlpha), double(k));
        double worst = 0.0;
        size_t checked = 0;
        uint32_t longest = 0;
        for (float sign : {1.0f, -1.0f}) {
            Camera cam;
            cam.eye = glm::vec3(0.0f);
            cam.target = glm::vec3(sign);
            cam.up = glm::vec3(0.0f, 1.0f, 0.0f);
            cam.fovy = glm::radians(110.0f);
            const DsmRun run = renderDsm(s, cam, kSize, kSize, Aov::Transmittance, {});
            EXPECT_EQ(run.stats.overflow, 0u);
            longest = std::max(longest, run.stats.longest);
            for (uint32_t py = 0; py < kSize; ++py)
                for (uint32_t px = 0; px < kSize; ++px) {
                    dvec3 d = glm::abs(cameraRay(cam, kSize, kSize, px, py).dir);
                    std::sort(&d[0], &d[0] + 3);
                    if (d[1] > 0.9 * d[2]) continue;  // near an edge of the cubes (and a seam of the faces)
                    worst = std::max(worst, std::abs(double(run.image.at(px, py)) - expected));
                    ++checked;
                }
        }
        std::printf("[dsm point] k=%u: %zu wall pixels, T max error %.2e against %.6f; longest list %u\n", k, checked,
                    worst, expected, longest);
        EXPECT_GT(checked, 2000u);
        EXPECT_LT(worst, 1e-3) << "k = " << k;
        EXPECT_EQ(longest, k);
    }
}

// A pool of 100 nodes for thousands of fragments: the overflow is counted exactly, reported as a
// warning, and the image (lit and transmittance) stays finite and in range.
// A pool too small for the runs drops whole 8x8 tiles of texels (dsm/offsets.comp), counted
// exactly: every fragment is then kept, dropped beyond the cap or dropped with its tile, and the
// warning names the number. A pool of 100 entries holds no full tile (8 layers x 64 texels); half
// the entries a roomy pool uses holds some.
TEST_F(DsmTest, PoolOverflowIsReportedAndImageStaysFinite) {
    const Scene s = stackedLayers(std::vector<float>(8, 0.3f), shuffled(8, 3));
    const DsmRun roomy = renderDsm(s, topCamera(), kW, kH, Aov::Transmittance, {});
    ASSERT_EQ(roomy.stats.overflow, 0u);
    for (uint64_t pool : {uint64_t(100), roomy.stats.sorted / 2})
        for (Aov aov : {Aov::Transmittance, Aov::Final}) {
            DsmSettings dsm;
            dsm.poolNodes = pool;
            const DsmRun run = renderDsm(s, topCamera(), kW, kH, aov, dsm);
            size_t bad = 0;
            for (float v : run.image.rgba) {
                const bool ok = std::isfinite(v) && v >= 0.0f && (aov != Aov::Transmittance || v <= 1.0f);
                if (!ok && bad == 0) std::printf("first bad value %g\n", double(v));
                bad += !ok;
            }
            std::printf("[dsm overflow] %llu fragments for a pool of %llu: %llu dropped, %llu nodes kept; warning: %s\n",
                        (unsigned long long)run.stats.fragments, (unsigned long long)run.stats.capacity,
                        (unsigned long long)run.stats.overflow, (unsigned long long)run.stats.kept,
                        run.warnings.empty() ? "(none)" : run.warnings.back().c_str());
            EXPECT_EQ(bad, 0u);
            EXPECT_EQ(run.stats.fragments, roomy.stats.fragments);
            EXPECT_GT(run.stats.overflow, 0u);
            EXPECT_EQ(run.stats.overflow + run.stats.kept + run.stats.beyondMaxList, run.stats.fragments);
            EXPECT_LE(run.stats.sorted, pool);
            if (pool == 100) EXPECT_EQ(run.stats.overflow, run.stats.fragments);
            else EXPECT_GT(run.stats.kept, 0u);
            ASSERT_FALSE(run.warnings.empty());
            EXPECT_NE(run.warnings.back().find(std::to_string(run.stats.overflow) + " of"), std::string::npos);
        }
}

// An opaque plate under the left part of 6 layers (x < -0.2, between the light below and the
// layers): with the depth test against the opaque casters' shadow map, the layer fragments above it
// take no node, and every receiver the plate leaves lit (the ceiling plate, x > 0.2) gets the same
// transmittance as without the test.
TEST_F(DsmTest, DepthTestedBuildKeepsTransmittanceWithFewerNodes) {
    Scene s = stackedLayers(std::vector<float>(6, 0.3f), shuffled(6, 11));
    addQuad(s, {-2.0f, 0.8f, -2.0f}, {1.8f, 0, 0}, {0, 0, 4}, addMaterial(s, glm::vec3(0.5f)));  // faces down
    s.computeBounds();
    DsmSettings on, off;
    on.depthTest = true;
    off.depthTest = false;
    const DsmRun tested = renderDsm(s, topCamera(), kW, kH, Aov::Transmittance, on, 256);
    const DsmRun untested = renderDsm(s, topCamera(), kW, kH, Aov::Transmittance, off, 256);
    const auto lit = platePixels(kCeilingY, true);
    double diff = 0.0;
    for (auto [x, y] : lit) diff = std::max(diff, double(std::abs(tested.image.at(x, y) - untested.image.at(x, y))));
    const double err = maxError(tested.image, lit, std::pow(0.7, 6.0));
    std::printf("[dsm depth test] nodes kept %llu with the test (%llu fragments skipped) vs %llu without; lit "
                "receivers differ by at most %.2e, error against 0.7^6 %.2e\n",
                (unsigned long long)tested.stats.kept, (unsigned long long)tested.stats.hidden,
                (unsigned long long)untested.stats.kept, diff, err);
    EXPECT_EQ(untested.stats.hidden, 0u);
    EXPECT_GT(tested.stats.hidden, 0u);
    EXPECT_LT(tested.stats.kept, untested.stats.kept * 3 / 4);  // the plate hides ~45% of the layers
    EXPECT_EQ(tested.stats.kept + tested.stats.hidden, untested.stats.kept);
    EXPECT_LT(diff, 1e-6);
    EXPECT_LT(err, 1e-3);
}
