// Hair and deep shadow maps beyond the closed-form cases of dsm_test.cpp: the built-in `hair` scene,
// glTF LINES / LINE_STRIP loading as strands, the invariants of the resolved lists and neighbour
// links read back from the GPU, soft (partial) hair shadows under a DSM against the binary ones of an
// ordinary shadow map, the hair's shadow at its points, the compute raster against the hardware, and
// frame-to-frame repeatability. The DSM options on the command line: dsm_cli_test.cpp.
#include <algorithm>
#include <fstream>
#include <map>

#include <fmt/format.h>
#include <glm/gtc/packing.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_run.h"
#include "gpu_fixture.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

// A glTF with only lines: a LINE_STRIP of 3 points, and LINES [0,1, 1,2, 3,4] over 5 points (one
// chained strand of 3 points and one of 2), under a node scaled by 2, with a BLEND material.
std::string writeLinesGltf(const ScratchDir& dir) {
    std::vector<float> pos{0, 0, 0, 0, -1, 0, 0.1f, -2, 0,                         // strip
                           1, 0, 0, 1, -1, 0, 1, -2, 0, 2, 0, 0, 2, -1, 0};          // lines
    std::vector<uint16_t> idx{0, 1, 1, 2, 3, 4};
    std::ofstream bin(dir.file("lines.bin"), std::ios::binary);
    bin.write(reinterpret_cast<const char*>(pos.data()), std::streamsize(pos.size() * 4));
    bin.write(reinterpret_cast<const char*>(idx.data()), std::streamsize(idx.size() * 2));
    bin.close();
    using nlohmann::json;
    const json strip{{"attributes", {{"POSITION", 0}}}, {"mode", 3}, {"material", 0}};
    const json lines{{"attributes", {{"POSITION", 1}}}, {"indices", 2}, {"mode", 1}, {"material", 0}};
    const json material{{"alphaMode", "BLEND"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.4, 0.3, 0.25}}}}};
    const json doc{
        {"asset", {{"version", "2.0"}}},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}, {"scale", {2, 2, 2}}}}},
        {"meshes", {{{"primitives", {strip, lines}}}}},
        {"materials", {material}},
        {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
                       {{"bufferView", 1}, {"componentType", 5126}, {"count", 5}, {"type", "VEC3"}},
                       {{"bufferView", 2}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}},
        {"bufferViews", {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
                         {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 60}},
                         {{"buffer", 0}, {"byteOffset", 96}, {"byteLength", 12}}}},
        {"buffers", {{{"uri", "lines.bin"}, {"byteLength", 108}}}},
    };
    std::ofstream(dir.file("lines.gltf")) << doc.dump(1);
    return dir.file("lines.gltf");
}



Scene hairScene(uint32_t strands) {
    BuiltinOptions options;
    options.hairStrands = strands;
    return makeBuiltinScene("hair", options);
}

// A small frame with deep shadow maps keeping `maxList` nodes a texel.
RenderSettings dsmFrame(uint32_t width, uint32_t height, uint32_t shadowResolution, uint32_t maxList) {
    RenderSettings rs;
    rs.width = width;
    rs.height = height;
    rs.shadow.resolution = shadowResolution;
    rs.dsm.enabled = true;
    rs.dsm.maxList = maxList;
    return rs;
}

}  // namespace

TEST(HairScene, GrowsTheRequestedStrandsOutsideTheHead) {
    BuiltinOptions options;
    options.hairStrands = 500;
    const Scene s = makeBuiltinScene("hair", options);
    ASSERT_EQ(s.strands.size(), 500u);
    const glm::vec3 head(0.0f, 0.42f, 0.0f);
    size_t inside = 0;
    for (const Strand& strand : s.strands) {
        ASSERT_GE(strand.pointCount, 2u);
        ASSERT_LE(size_t(strand.firstPoint) + strand.pointCount, s.strandPoints.size());
        for (uint32_t i = 0; i < strand.pointCount; ++i) {
            const glm::vec3& p = s.strandPoints[strand.firstPoint + i];
            inside += glm::length(p - head) < 0.1f * 0.999f;
            EXPECT_GE(p.x, s.bounds.min.x);
            EXPECT_LE(p.y, s.bounds.max.y);
        }
    }
    EXPECT_EQ(inside, 0u) << "strand points inside the head sphere";
    EXPECT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, LightType::Spot);
    // Same seed, same hair.
    EXPECT_EQ(makeBuiltinScene("hair", options).strandPoints, s.strandPoints);
}

TEST(HairScene, GltfLinesLoadAsStrands) {
    ScratchDir dir;
    const Scene s = loadScene(writeLinesGltf(dir));
    ASSERT_EQ(s.strands.size(), 3u);
    EXPECT_EQ(s.strands[0].pointCount, 3u);  // LINE_STRIP
    EXPECT_EQ(s.strands[1].pointCount, 3u);  // LINES 0-1, 1-2 chained
    EXPECT_EQ(s.strands[2].pointCount, 2u);  // LINES 3-4
    EXPECT_EQ(s.indices.size(), 0u);
    for (const Strand& st : s.strands) {
        EXPECT_FLOAT_EQ(st.opacity, 0.25f);                      // BLEND alpha
        EXPECT_NEAR(st.color.r, 0.5f, 1e-6f);
        EXPECT_NEAR(st.width, 2.0f * Strand{}.width, 1e-9f);     // scaled with the node
    }
    EXPECT_EQ(s.strandPoints[2], glm::vec3(0.2f, -4.0f, 0.0f));  // node transform applied
    EXPECT_FALSE(s.bounds.empty());
}

// The hair-only glTF renders (SceneGpu without triangles) with a DSM, under validation.
TEST_F(GpuTest, HairOnlyGltfRenders) {
    ScratchDir dir;
    const Scene s = loadScene(writeLinesGltf(dir));
    RenderSettings rs;
    rs.width = 32;
    rs.height = 32;
    rs.shadow.resolution = 64;
    rs.dsm.enabled = true;
    TestRenderer r(ctx(), s, rs);
    r.render(s.cameras[0]);
    EXPECT_GT(r.deepShadows().readStats(r.commands()).fragments, 0u);
}

// After a frame of the hair scene: every list is sorted by depth, packed in consecutive nodes, at
// most maxList long, its length stored for the binary search, its transmittance falls from node to
// node, and (`--dsm-lookup links`) every neighbour link points at the node of the neighbour's list
// with the largest depth <= the node's own.
TEST_F(GpuTest, DsmListsAndLinksAreConsistent) {
    const Scene s = hairScene(2000);
    RenderSettings rs = dsmFrame(64, 48, 128, 12);
    rs.dsm.lookup = DsmLookup::Links;
    TestRenderer r(ctx(), s, rs);
    r.render(s.cameras[0]);
    const DsmResources& res = r.deepShadows().resources();
    const DsmFrameStats st = r.deepShadows().readStats(r.commands());
    ASSERT_EQ(st.overflow, 0u);
    const uint32_t n = res.resolution;
    auto heads = r.commands().readBuffer(res.heads, VkDeviceSize(n) * n * 4 * DSM_HEAD_UINTS);  // head, length, ...
    // The resolve packs the sorted lists after the build's nodes (dsm/resolve.comp).
    const uint64_t used = std::min<uint64_t>(st.fragments + st.kept, res.capacity);
    auto nodeBytes = r.commands().readBuffer(res.nodes, used * 16);
    auto upBytes = r.commands().readBuffer(res.side, used * 4);
    const auto* head = reinterpret_cast<const uint32_t*>(heads.data());
    const auto* node = reinterpret_cast<const glm::uvec4*>(nodeBytes.data());
    const auto* up = reinterpret_cast<const uint32_t*>(upBytes.data());
    auto depth = [&](uint32_t i) { return glm::uintBitsToFloat(node[i].x); };
    std::vector<int64_t> owner(used, -1);
    uint64_t kept = 0;
    size_t unsorted = 0, rising = 0, tooLong = 0, scattered = 0, wrongLength = 0;
    for (uint32_t t = 0; t < n * n; ++t) {
        uint32_t len = 0;
        float lastDepth = -1e30f, lastT = 1.0f;
        for (uint32_t i = head[t * DSM_HEAD_UINTS]; i != DSM_NONE && len <= rs.dsm.maxList; i = node[i].z, ++len) {
            owner[i] = t;
            scattered += node[i].z != DSM_NONE && node[i].z != i + 1;  // packed: each list in consecutive nodes
            unsorted += depth(i) < lastDepth;
            rising += glm::uintBitsToFloat(node[i].y) > lastT;
            lastDepth = depth(i);
            lastT = glm::uintBitsToFloat(node[i].y);
        }
        tooLong += len > rs.dsm.maxList;
        wrongLength += head[t * DSM_HEAD_UINTS] != DSM_NONE && head[t * DSM_HEAD_UINTS + 1] != len;
        kept += len;
    }
    // A link from node i of texel t to texel u (DSM_NONE: u has nothing at or in front of i).
    size_t badLinks = 0, links = 0;
    auto checkLink = [&](uint32_t i, uint32_t link, uint32_t u) {
        ++links;
        uint32_t expected = DSM_NONE;
        for (uint32_t j = head[u * DSM_HEAD_UINTS]; j != DSM_NONE && depth(j) <= depth(i); j = node[j].z) expected = j;
        badLinks += link != expected;
    };
    for (uint32_t i = 0; i < used; ++i) {
        if (owner[i] < 0) continue;
        const uint32_t t = uint32_t(owner[i]), x = t % n, y = t / n;
        if (x + 1 < n) checkLink(i, node[i].w, t + 1);
        if (y + 1 < n) checkLink(i, up[i], t + n);
    }
    std::printf("[dsm lists] %llu nodes in %llu lists (longest %u before the cap of %u): %zu unsorted, %zu "
                "transmittance rises, %zu too long, %zu wrong lengths, %zu nodes not followed by their list's next; "
                "%zu of %zu links wrong\n",
                (unsigned long long)kept, (unsigned long long)st.lists, st.longest, rs.dsm.maxList, unsorted, rising,
                tooLong, wrongLength, scattered, badLinks, links);
    EXPECT_EQ(kept, st.kept);
    EXPECT_GT(st.longest, rs.dsm.maxList);  // the cap was exercised
    EXPECT_EQ(unsorted + rising + tooLong + wrongLength, 0u);
    EXPECT_EQ(scattered, 0u);
    EXPECT_GT(links, 1000u);
    EXPECT_EQ(badLinks, 0u);
}

// The binary-search lookup (default) finds the same node in every tap as the walk through the
// neighbour links: bit-equal images from the lighting pass (hair opaque in the G-buffer) and the
// translucency composite, for bilinear taps, the default 3x3 and a 5x5 kernel (searched tap after
// tap), with the pool roomy and just large enough for the build's fragments.
TEST_F(GpuTest, DsmSearchLookupEqualsTheLinkWalk) {
    const Scene s = hairScene(2000);
    auto render = [&](DsmLookup lookup, float width, uint64_t pool, bool translucency, DsmFrameStats* stats) {
        RenderSettings rs = dsmFrame(96, 72, 128, 24);
        rs.gi = GiMode::None;
        rs.dsm.lookup = lookup;
        rs.dsm.filterWidth = width;
        rs.dsm.poolNodes = pool;
        rs.translucency = translucency;
        rs.aov = translucency ? Aov::Final : Aov::Direct;
        TestRenderer r(ctx(), s, rs);
        r.render(s.cameras[0]);
        if (stats) *stats = r.deepShadows().readStats(r.commands());
        return r.readHdr();
    };
    DsmFrameStats roomy;
    render(DsmLookup::Links, 1.0f, 0, false, &roomy);
    const uint64_t tight = roomy.fragments;  // the sorted lists reuse the build's nodes
    size_t compared = 0, differing = 0, lit = 0;
    for (uint64_t pool : {uint64_t(0), tight})
        for (float width : {0.0f, 1.0f, 3.0f})
            for (bool translucency : {false, true}) {
                DsmFrameStats st;
                const std::vector<float> links = render(DsmLookup::Links, width, pool, translucency, &st);
                const std::vector<float> search = render(DsmLookup::Search, width, pool, translucency, nullptr);
                ASSERT_EQ(st.overflow, 0u);
                ASSERT_EQ(links.size(), search.size());
                for (size_t i = 0; i < links.size(); ++i) {
                    differing += links[i] != search[i];
                    lit += links[i] > 0.0f;
                }
                compared += links.size();
            }
    std::printf("[dsm search] %zu values compared (%zu lit), %zu differ; tight pool %llu nodes for %llu fragments\n",
                compared, lit, differing, (unsigned long long)tight, (unsigned long long)roomy.fragments);
    EXPECT_GT(lit, compared / 8);
    EXPECT_EQ(differing, 0u);
}

namespace {

// Integral of the unit tent from -inf to t, and the weight of texel i for a box of `width` texels
// centred at s (dsm/dsm_lookup.glsl's filter, written again in double).
double tentCdf(double t) {
    t = std::clamp(t, -1.0, 1.0);
    return t < 0.0 ? 0.5 * (t + 1.0) * (t + 1.0) : 1.0 - 0.5 * (1.0 - t) * (1.0 - t);
}
double tapWeight(double s, double width, int i) {
    const double c = i + 0.5;
    if (width < 1e-3) return std::max(0.0, 1.0 - std::abs(s - c));
    return (tentCdf(s + 0.5 * width - c) - tentCdf(s - 0.5 * width - c)) / width;
}

// The filtered transmittance of a hair receiver at p in one DSM (a directional or spot light's),
// from the resolved lists read back: per tap the transmittance behind the last node at or in front
// of the receiver's depth.
double listTransmittance(const gpu::GpuDsmLight& dsm, const glm::dvec3& p, const uint32_t* heads,
                         const glm::uvec4* nodes) {
    const glm::dvec3 viewer(dsm.viewer);
    const bool spot = dsm.viewerIsPoint != 0;
    const double texel = dsm.texelSize * (dsm.projection != DSM_PROJECTION_ORTHO ? glm::distance(p, viewer) : 1.0);
    const glm::dvec3 q = p + (spot ? glm::normalize(viewer - p) : viewer) * (dsm.normalOffset * texel);
    const glm::dvec4 clip = glm::dmat4(dsm.viewProj) * glm::dvec4(q, 1.0);
    if (clip.w <= 0.0) return 1.0;
    const int res = int(dsm.resolution);
    const double width = dsm.filterWidth, d = (spot ? glm::distance(q, viewer) : -glm::dot(q, viewer)) - dsm.depthBias * texel;
    const glm::dvec2 s = (glm::dvec2(clip) / clip.w * 0.5 + 0.5) * double(res);
    const glm::ivec2 lo(glm::floor(s - 0.5 * width - 0.5)), hi = glm::ivec2(glm::floor(s + 0.5 * width - 0.5)) + 1;
    double sum = 0.0;
    for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x) {
            double t = 1.0;
            if (x >= 0 && y >= 0 && x < res && y < res) {
                const uint32_t texelIndex = uint32_t(dsm.layer) * res * res + y * res + x;
                const uint32_t first = heads[texelIndex * DSM_HEAD_UINTS], length = heads[texelIndex * DSM_HEAD_UINTS + 1];
                for (uint32_t k = 0; first != DSM_NONE && k < length && glm::uintBitsToFloat(nodes[first + k].x) <= d; ++k)
                    t = glm::uintBitsToFloat(nodes[first + k].y);
            }
            sum += tapWeight(s.y, width, y) * tapWeight(s.x, width, x) * t;
        }
    return std::min(sum, 1.0);
}

}  // namespace

// The hair's own shadow (oit.hair-shadow: what the camera's hair layers interpolate along their
// segments) at every drawn hair point equals the DSM lookup there, computed again on the CPU in
// double from the lists read back; for two lights (the hair scene's spot, and a sun), which also
// checks the points' Morton order and the lights' layout. The strands alone, without the head and
// floor: no opaque caster, so that the ordinary shadow maps leave every point lit.
TEST_F(GpuTest, HairShadowEqualsTheListsAtEveryPoint) {
    const Scene full = hairScene(2000);
    Scene s;
    s.strandPoints = full.strandPoints;
    s.strands = full.strands;
    s.cameras = full.cameras;
    s.materials = full.materials;
    s.lights = full.lights;
    Light sun;
    sun.direction = glm::normalize(glm::vec3(0.4f, -1.0f, 0.3f));
    s.lights.push_back(sun);
    s.computeBounds();
    RenderSettings rs = dsmFrame(64, 48, 256, 16);
    rs.gi = GiMode::None;
    TestRenderer r(ctx(), s, rs);
    r.render(s.cameras[0]);
    const DsmResources& res = r.deepShadows().resources();
    ASSERT_EQ(res.layerCount(), 2u);
    ASSERT_EQ(r.deepShadows().readStats(r.commands()).overflow, 0u);
    ASSERT_NE(r.translucency(), nullptr);
    const HairGpu& hair = *r.hair();
    const uint32_t points = hair.pointCount(), texels = res.resolution * res.resolution * res.layerCount();
    const auto pointBytes = r.commands().readBuffer(hair.points(), points * sizeof(gpu::GpuHairPoint));
    const auto strandBytes = r.commands().readBuffer(r.translucency()->hairShadow(), 2 * points * 4);
    const auto headBytes = r.commands().readBuffer(res.heads, VkDeviceSize(texels) * 4 * DSM_HEAD_UINTS);
    const auto nodeBytes = r.commands().readBuffer(res.nodes, res.capacity * 16);
    const auto* point = reinterpret_cast<const gpu::GpuHairPoint*>(pointBytes.data());
    const auto* strand = reinterpret_cast<const float*>(strandBytes.data());
    const auto* table = reinterpret_cast<const gpu::GpuDsmLight*>(res.lightTable.current().mapped());
    size_t compared = 0, differing = 0, shadowed[2] = {0, 0};
    double worst = 0.0, sumError = 0.0;
    for (uint32_t light = 0; light < 2; ++light)
        for (uint32_t i = 0; i < points; ++i) {
            if (point[i].width <= 0.0f) continue;  // the zero-width copies bracketing a strand: never drawn
            const double cpu = listTransmittance(table[light], glm::dvec3(point[i].position),
                                                 reinterpret_cast<const uint32_t*>(headBytes.data()),
                                                 reinterpret_cast<const glm::uvec4*>(nodeBytes.data()));
            const double error = std::abs(strand[light * points + i] - cpu);
            ++compared;
            shadowed[light] += cpu < 0.99;
            differing += error > 1e-4;
            worst = std::max(worst, error);
            sumError += error;
        }
    std::printf("[hair shadow] %zu point lookups (with T < 0.99: %zu spot, %zu sun): %zu differ by > 1e-4 (worst "
                "%.2e, mean %.2e)\n",
                compared, shadowed[0], shadowed[1], differing, worst, sumError / double(compared));
    EXPECT_GT(std::min(shadowed[0], shadowed[1]), compared / 20);  // both maps shadow many points
    // A receiver within float rounding of a node's depth may fall on either side of it.
    EXPECT_LT(differing, compared / 1000 + 1);
    EXPECT_LT(sumError / double(compared), 1e-5);
}

// Shadow visibility (opaque map x DSM transmittance) of the hair's own pixels: with a DSM a large
// share of the shadowed ones is partly lit; with hair in the ordinary (hard) shadow map almost none is.
TEST_F(GpuTest, HairShadowsArePartialWithDsmAndBinaryWithout) {
    BuiltinOptions options;
    options.hairStrands = 3000;
    const Scene s = makeBuiltinScene("hair", options);
    std::map<bool, double> partialShare;
    for (bool dsm : {false, true}) {
        RenderSettings rs;
        rs.width = 128;
        rs.height = 96;
        rs.aov = Aov::Shadow;
        rs.shadow.resolution = 256;
        rs.dsm.enabled = dsm;
        rs.translucency = false;  // hair in the G-buffer, where the shadow AOV and SHADING_HAIR are per pixel
        TestRenderer r(ctx(), s, rs);
        r.render(s.cameras[0]);
        const std::vector<float> img = r.readHdr();
        const std::vector<uint8_t> normal = r.commands().readImage(r.gbuffer().normal, 8);
        size_t shadowed = 0, partial = 0;
        for (size_t i = 0; i < img.size() / 4; ++i) {
            uint16_t w;
            std::memcpy(&w, normal.data() + i * 8 + 6, 2);
            if (glm::unpackHalf1x16(w) < 1.5f) continue;  // not hair (SHADING_HAIR in the normal's w)
            shadowed += img[i * 4] < 0.95f;
            partial += img[i * 4] > 0.05f && img[i * 4] < 0.95f;
        }
        partialShare[dsm] = shadowed ? double(partial) / double(shadowed) : 0.0;
        std::printf("[hair shadows] %s: %zu shadowed hair pixels, %.1f%% of them partly lit\n",
                    dsm ? "deep shadow map" : "shadow map", shadowed, 100.0 * partialShare[dsm]);
        EXPECT_GT(shadowed, 300u);
    }
    EXPECT_GT(partialShare[true], 0.3);
    EXPECT_LT(partialShare[false], 0.05);
}

// Hair ribbons rasterized in compute (`--raster compute`: dsm/ribbon_raster.glsl walks each
// segment's quad) against the raster hardware drawing the same quads: both builds (the light's DSM
// and the camera's translucency lists) get the same fragments but for pixel centres within rounding
// of a ribbon's edge, and the images agree: the DSM-shadowed direct light (hair in the G-buffer) and
// the composited hair (lists sorted by depth, which the walk takes from the segment's centre line
// where the hardware interpolates the quad's corners).
TEST_F(GpuTest, HairComputeRasterEqualsTheHardware) {
    BuiltinOptions options;
    options.hairStrands = 400;  // lists mostly under the 32-fragment cap (the cap's merged tail takes its radiance
                                // from the 32nd fragment: a depth rounded differently there changes a whole pixel)
    const Scene s = makeBuiltinScene("hair", options);
    struct Result {
        uint64_t dsmFragments = 0, oitFragments = 0;
        std::vector<float> direct, final;
    };
    std::map<RasterMode, Result> results;
    for (RasterMode mode : {RasterMode::Hardware, RasterMode::Compute}) {
        Result& out = results[mode];
        for (bool translucency : {false, true}) {
            RenderSettings rs = dsmFrame(160, 120, 512, DsmSettings{}.maxList);
            rs.shadow.raster = mode;
            rs.translucency = translucency;
            rs.aov = translucency ? Aov::Final : Aov::Direct;
            TestRenderer r(ctx(), s, rs);
            r.render(s.cameras[0]);
            (translucency ? out.final : out.direct) = r.readHdr();
            if (!translucency) out.dsmFragments = r.deepShadows().readStats(r.commands()).fragments;
            if (translucency) out.oitFragments = r.translucency()->readStats(r.commands()).fragments;
        }
    }
    const Result &hw = results[RasterMode::Hardware], &cs = results[RasterMode::Compute];
    auto relL2 = [](const std::vector<float>& a, const std::vector<float>& b, size_t& differing) {
        double d2 = 0, b2 = 0;
        differing = 0;
        for (size_t i = 0; i < a.size(); i += 4) {
            double pixel = 0;
            for (size_t c = 0; c < 3; ++c) {
                d2 += double(a[i + c] - b[i + c]) * (a[i + c] - b[i + c]);
                b2 += double(b[i + c]) * b[i + c];
                pixel = std::max(pixel, std::abs(double(a[i + c] - b[i + c])));
            }
            differing += pixel > 0.01;
        }
        return std::sqrt(d2 / b2);
    };
    size_t directDiffering = 0, finalDiffering = 0;
    const double direct = relL2(cs.direct, hw.direct, directDiffering), final = relL2(cs.final, hw.final, finalDiffering);
    const size_t pixels = hw.final.size() / 4;
    std::printf("[hair compute raster] DSM fragments %llu (hardware %llu), camera fragments %llu (hardware %llu); "
                "direct rel L2 %.4f (%zu of %zu pixels > 0.01), final rel L2 %.4f (%zu pixels > 0.01)\n",
                (unsigned long long)cs.dsmFragments, (unsigned long long)hw.dsmFragments,
                (unsigned long long)cs.oitFragments, (unsigned long long)hw.oitFragments, direct, directDiffering,
                pixels, final, finalDiffering);
    EXPECT_GT(hw.dsmFragments, 20000u);
    EXPECT_GT(hw.oitFragments, 10000u);
    EXPECT_NEAR(double(cs.dsmFragments), double(hw.dsmFragments), 1e-3 * double(hw.dsmFragments));
    EXPECT_NEAR(double(cs.oitFragments), double(hw.oitFragments), 1e-3 * double(hw.oitFragments));
    EXPECT_LT(direct, 0.01);
    EXPECT_LT(final, 0.01);
}

// The same frame twice gives the same image: the builds' atomics put the fragments in their runs in
// a different order each run, and fragments of equal depth (a strand's consecutive segments meet at
// one point) must not trade places at the composite's 32-layer cap or the DSM's list cap, or a
// pixel's merged tail takes another layer's radiance (up to 0.9 in a run at 480x270 before the tie
// keys of dsm/oit_sort.comp and dsm/resolve.comp).
TEST_F(GpuTest, HairCompositeIsTheSameFromRunToRun) {
    const Scene s = hairScene(5000);
    RenderSettings rs = dsmFrame(160, 120, 512, 12);
    rs.shadow.raster = RasterMode::Compute;
    std::vector<float> first;
    double worst = 0.0;
    uint64_t merged = 0;
    for (int run = 0; run < 4; ++run) {
        TestRenderer r(ctx(), s, rs);
        r.render(s.cameras[0]);
        const std::vector<float> image = r.readHdr();
        merged = r.translucency()->readStats(r.commands()).beyondMaxList;
        if (run == 0) first = image;
        for (size_t i = 0; i < image.size(); ++i)
            worst = std::max(worst, std::abs(double(image[i]) - first[i]) / std::max(1e-3, std::abs(double(first[i]))));
    }
    std::printf("[hair runs] largest relative difference between 4 runs %.2e (%llu fragments merged beyond the cap)\n",
                worst, (unsigned long long)merged);
    EXPECT_GT(merged, 10000u);  // the cap is exercised
    EXPECT_LT(worst, 1e-4);
}

// Frame after frame one renderer gives the same image and the same counts: the builds' per-cell
// counts are filled with zero only in the first frame, after which their last readers (the DSM's
// resolve, the camera's sort) zero the cells they counted. With a pool too small for the DSM's runs
// (tiles dropped, their texels counted but given no run: which ones depends on the order of the
// tiles' atomics, so there only the counts are compared) as well as with the default one.
TEST_F(GpuTest, CountsStartFromZeroEveryFrame) {
    const Scene s = hairScene(2000);
    for (uint64_t pool : {uint64_t(0), uint64_t(20000)}) {
        RenderSettings rs = dsmFrame(160, 120, 256, DsmSettings{}.maxList);
        rs.shadow.raster = RasterMode::Compute;
        rs.dsm.poolNodes = pool;
        TestRenderer r(ctx(), s, rs);
        std::vector<float> first;
        DsmFrameStats dsmFirst;
        OitFrameStats oitFirst;
        for (int frame = 0; frame < 3; ++frame) {
            r.render(s.cameras[0]);
            const std::vector<float> image = r.readHdr();
            const DsmFrameStats dsm = r.deepShadows().readStats(r.commands());
            const OitFrameStats oit = r.translucency()->readStats(r.commands());
            if (frame == 0) {
                first = image, dsmFirst = dsm, oitFirst = oit;
                EXPECT_GT(dsm.fragments, 10000u);
                EXPECT_GT(oit.fragments, 10000u);
                EXPECT_EQ(dsm.overflow > 0, pool > 0) << dsm.overflow;  // the small pool drops tiles
                continue;
            }
            EXPECT_EQ(dsm.fragments, dsmFirst.fragments) << "frame " << frame << ", pool " << pool;
            EXPECT_EQ(oit.fragments, oitFirst.fragments) << "frame " << frame;
            if (pool > 0) continue;  // which tiles find room depends on the order of their atomics
            EXPECT_EQ(dsm.overflow, 0u) << "frame " << frame;
            EXPECT_EQ(dsm.kept, dsmFirst.kept) << "frame " << frame;
            EXPECT_EQ(oit.kept, oitFirst.kept) << "frame " << frame;
            double worst = 0.0;
            for (size_t i = 0; i < image.size(); ++i)
                worst = std::max(worst, std::abs(double(image[i]) - first[i]) / std::max(1e-3, std::abs(double(first[i]))));
            EXPECT_LT(worst, 1e-4) << "frame " << frame << ", pool " << pool;
        }
    }
}

// Every pixel of the hair scene is finite at 1280x720 with camera translucency: lavapipe's raster
// gave one fragment of a degenerate strip join non-finite interpolants (a NaN pixel at (587, 476),
// found by `eval --hair`), which the list builds now drop.
TEST_F(GpuTest, HairTranslucencyImageIsFinite) {
    const Scene s = makeBuiltinScene("hair", BuiltinOptions{});
    RenderSettings rs;
    rs.width = 1280;
    rs.height = 720;
    rs.gi = GiMode::None;
    rs.shadow.filter = ShadowFilter::Hard;
    TestRenderer r(ctx(), s, rs);
    r.render(s.cameras[0]);
    const std::vector<float> img = r.readHdr();
    size_t nonFinite = 0;
    for (float v : img) nonFinite += !std::isfinite(v);
    EXPECT_EQ(nonFinite, 0u);
}
