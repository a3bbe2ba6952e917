// Unit tests of the shadow module's math (no GPU): cascade splits and fits, their stability under
// camera motion, cube-face and dual-paraboloid projections, the layer assignment and the shadow
// options' parsing.
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "frame/light_filters.h"
#include "shadow/cascades.h"
#include "shadow/shadow_layout.h"

using namespace penumbra;

namespace {

glm::vec3 ndcOf(const glm::mat4& m, const glm::vec3& p) {
    const glm::vec4 c = m * glm::vec4(p, 1.0f);
    return glm::vec3(c) / c.w;
}

Bounds box(float half) {
    Bounds b;
    b.extend(glm::vec3(-half));
    b.extend(glm::vec3(half));
    return b;
}

Camera lookingAt(glm::vec3 eye, glm::vec3 target, float fovyDegrees = 50.0f) {
    Camera c;
    c.eye = eye;
    c.target = target;
    c.fovy = glm::radians(fovyDegrees);
    return c;
}

}  // namespace

TEST(Cascades, PracticalSplitsBlendUniformAndLogarithmic) {
    const std::vector<float> uniform = cascadeSplits(1.0f, 100.0f, 4, 0.0f);
    const std::vector<float> logarithmic = cascadeSplits(1.0f, 100.0f, 4, 1.0f);
    const std::vector<float> mixed = cascadeSplits(1.0f, 100.0f, 4, 0.75f);
    ASSERT_EQ(uniform.size(), 5u);
    for (int i = 0; i <= 4; ++i) {
        EXPECT_NEAR(uniform[i], 1.0f + 99.0f * float(i) / 4.0f, 1e-4f);
        EXPECT_NEAR(logarithmic[i], std::pow(100.0f, float(i) / 4.0f), 1e-3f);
        EXPECT_NEAR(mixed[i], 0.75f * logarithmic[i] + 0.25f * uniform[i], 1e-3f);
        if (i > 0) {
            EXPECT_GT(mixed[i], mixed[i - 1]);
        }
    }
    EXPECT_FLOAT_EQ(mixed.front(), 1.0f);
    EXPECT_FLOAT_EQ(mixed.back(), 100.0f);
}

TEST(Cascades, FarPlaneIsQuantised) {
    // Small camera moves leave the far end (and so every split) unchanged.
    EXPECT_EQ(cascadeFar(100.0f), cascadeFar(100.5f));
    EXPECT_GE(cascadeFar(100.0f), 100.0f);
    EXPECT_LT(cascadeFar(100.0f), 100.0f * 1.19f);
}

TEST(Cascades, SliceSphereEnclosesTheSliceAndTouchesIt) {
    const Camera cam = lookingAt({3, 2, 7}, {-1, 0.5f, -2}, 55.0f);
    const float aspect = 16.0f / 9.0f, n = 2.0f, f = 9.0f;
    const Sphere s = frustumSliceSphere(cam, aspect, n, f);
    const glm::mat4 invView = glm::inverse(glm::lookAt(cam.eye, cam.target, cam.up));
    const float ty = std::tan(0.5f * cam.fovy), tx = ty * aspect;
    float farthest = 0.0f;
    for (int i = 0; i < 8; ++i) {
        const float z = (i & 4) ? f : n;
        const glm::vec3 v{((i & 1) ? 1.0f : -1.0f) * z * tx, ((i & 2) ? 1.0f : -1.0f) * z * ty, -z};
        farthest = std::max(farthest, glm::length(glm::vec3(invView * glm::vec4(v, 1.0f)) - s.center));
    }
    EXPECT_LE(farthest, s.radius * (1.0f + 1e-5f));
    EXPECT_GE(farthest, s.radius * (1.0f - 1e-5f));  // minimal: a corner lies on it
}

TEST(Cascades, CameraTranslationMovesCascadesByWholeTexels) {
    const Bounds scene = box(50.0f);
    const glm::vec3 sun = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
    const uint32_t res = 1024;
    CascadeSettings cs;
    Camera a = lookingAt({10, 6, 12}, {0, 1, 0});
    const std::vector<Cascade> ca = fitCascades(sun, a, 1.5f, 80.0f, scene, res, cs, 4.0f);
    for (const glm::vec3 move : {glm::vec3(0.0123f, 0.0f, -0.0071f), glm::vec3(0.31f, 0.05f, 0.77f)}) {
        Camera b = a;
        b.eye += move;
        b.target += move;
        const std::vector<Cascade> cb = fitCascades(sun, b, 1.5f, 80.0f, scene, res, cs, 4.0f);
        for (size_t i = 0; i < ca.size(); ++i) {
            SCOPED_TRACE(i);
            EXPECT_FLOAT_EQ(ca[i].projection.texelSize, cb[i].projection.texelSize);
            // A fixed world point lands a whole number of texels apart in the two maps.
            const glm::vec3 p{1.7f, 0.3f, -2.9f};
            const glm::vec2 shift = (glm::vec2(ndcOf(ca[i].projection.viewProj, p)) -
                                     glm::vec2(ndcOf(cb[i].projection.viewProj, p))) * (0.5f * float(res));
            EXPECT_NEAR(shift.x, std::round(shift.x), 2e-3f);
            EXPECT_NEAR(shift.y, std::round(shift.y), 2e-3f);
        }
    }
    // Without snapping the same move shifts the texel grid by a fraction (what the GPU test shows as shimmer).
    cs.stabilize = false;
    Camera b = a;
    b.eye += glm::vec3(0.0123f, 0.0f, -0.0071f);
    b.target += glm::vec3(0.0123f, 0.0f, -0.0071f);
    const glm::mat4 m0 = fitCascades(sun, a, 1.5f, 80.0f, scene, res, cs, 4.0f)[0].projection.viewProj;
    const glm::mat4 m1 = fitCascades(sun, b, 1.5f, 80.0f, scene, res, cs, 4.0f)[0].projection.viewProj;
    const float shift = (ndcOf(m0, {0, 0, 0}).x - ndcOf(m1, {0, 0, 0}).x) * 0.5f * float(res);
    EXPECT_GT(std::abs(shift - std::round(shift)), 0.01f);
}

// GI reads the sun's map in blocks (an RSM texel is 4 shadow texels at 2048 / 512; a VPL more):
// with snapTexels = 8 a camera move shifts the lattice by whole blocks, and the slice stays covered.
TEST(Cascades, BlockSnappingMovesCascadesByWholeBlocksAndKeepsTheSliceCovered) {
    const Bounds scene = box(50.0f);
    const glm::vec3 sun = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
    const uint32_t res = 1024, block = 8;
    CascadeSettings cs;
    const float aspect = 1.5f;
    Camera a = lookingAt({10, 6, 12}, {0, 1, 0});
    const std::vector<Cascade> ca = fitCascades(sun, a, aspect, 80.0f, scene, res, cs, 4.0f, block);
    int moved = 0;
    for (float step = 0.05f; step < 3.0f; step *= 1.7f) {
        Camera b = a;
        b.eye += glm::vec3(step, 0.1f * step, -0.6f * step);
        b.target += glm::vec3(step, 0.1f * step, -0.6f * step);
        const std::vector<Cascade> cb = fitCascades(sun, b, aspect, 80.0f, scene, res, cs, 4.0f, block);
        for (size_t i = 0; i < ca.size(); ++i) {
            SCOPED_TRACE(i);
            const glm::vec3 p{1.7f, 0.3f, -2.9f};
            const glm::vec2 shift = (glm::vec2(ndcOf(ca[i].projection.viewProj, p)) -
                                     glm::vec2(ndcOf(cb[i].projection.viewProj, p))) * (0.5f * float(res) / float(block));
            EXPECT_NEAR(shift.x, std::round(shift.x), 2e-3f);
            EXPECT_NEAR(shift.y, std::round(shift.y), 2e-3f);
            moved += glm::length(shift) > 0.5f;
            // The slice's bounding sphere and the 4 margin texels around it still lie inside the map.
            const float start = i == 0 ? cb[i].splitNear : cb[i].splitNear - cs.blend * (cb[i].splitNear - cb[i - 1].splitNear);
            const Sphere s = frustumSliceSphere(b, aspect, start, cb[i].splitFar);
            if (s.radius >= scene.radius()) continue;  // the scene's sphere instead
            const glm::vec3 c = ndcOf(cb[i].projection.viewProj, s.center);
            const float r = s.radius / (0.5f * float(res) * cb[i].projection.texelSize);  // radius in NDC
            EXPECT_LE(std::max(std::abs(c.x), std::abs(c.y)) + r + 4.0f * 2.0f / float(res), 1.0f + 1e-4f);
        }
    }
    EXPECT_GT(moved, 0);  // the moves were large enough to shift some cascade
}

TEST(Cascades, CameraRotationKeepsTexelSize) {
    const Bounds scene = box(50.0f);
    const glm::vec3 sun = glm::normalize(glm::vec3(0.2f, -1.0f, 0.5f));
    CascadeSettings cs;
    const Camera a = lookingAt({10, 6, 12}, {0, 1, 0});
    const Camera b = lookingAt({10, 6, 12}, {14, -1, 3});  // turned and tilted
    const std::vector<Cascade> ca = fitCascades(sun, a, 1.5f, 80.0f, scene, 1024, cs, 4.0f);
    const std::vector<Cascade> cb = fitCascades(sun, b, 1.5f, 80.0f, scene, 1024, cs, 4.0f);
    for (size_t i = 0; i < ca.size(); ++i) EXPECT_NEAR(ca[i].projection.texelSize, cb[i].projection.texelSize, 1e-6f);
}

TEST(Cascades, EachCascadeCoversItsSliceIncludingTheBlendBand) {
    const Bounds scene = box(40.0f);
    const glm::vec3 sun = glm::normalize(glm::vec3(0.3f, -1.0f, 0.1f));
    CascadeSettings cs;
    const Camera cam = lookingAt({5, 4, 20}, {0, 0, 0});
    const float aspect = 1.6f;
    const std::vector<Cascade> cascades = fitCascades(sun, cam, aspect, 60.0f, scene, 512, cs, 4.0f);
    ASSERT_EQ(cascades.size(), 4u);
    const glm::mat4 invView = glm::inverse(glm::lookAt(cam.eye, cam.target, cam.up));
    const float ty = std::tan(0.5f * cam.fovy), tx = ty * aspect;
    for (size_t i = 0; i < cascades.size(); ++i) {
        const Cascade& c = cascades[i];
        if (i > 0) {
            EXPECT_FLOAT_EQ(c.splitNear, cascades[i - 1].splitFar);
        }
        const float start = i == 0 ? c.splitNear : c.splitNear - cs.blend * (c.splitNear - cascades[i - 1].splitNear);
        for (float z : {start, c.splitFar})
            for (float sx : {-1.0f, 1.0f})
                for (float sy : {-1.0f, 1.0f}) {
                    const glm::vec3 w = glm::vec3(invView * glm::vec4(sx * z * tx, sy * z * ty, -z, 1.0f));
                    if (glm::any(glm::greaterThan(glm::abs(w), glm::vec3(40.0f)))) continue;  // outside the scene
                    const glm::vec3 ndc = ndcOf(c.projection.viewProj, w);
                    EXPECT_LE(std::max(std::abs(ndc.x), std::abs(ndc.y)), 1.0f) << "cascade " << i;
                    EXPECT_GE(ndc.z, 0.0f);
                    EXPECT_LE(ndc.z, 1.0f);
                }
    }
}

TEST(PointLightMaps, CubeFaceOfTheMajorAxisHoldsEveryDirection) {
    const glm::vec3 pos{0.5f, 1.0f, -0.25f};
    const auto faces = cubeFaceProjections(pos, {0.01f, 10.0f}, 256, 2.0f);
    const glm::vec3 dirs[] = {{1, 0.2f, -0.99f}, {-1, 0.7f, 0.3f}, {0.1f, 1, 0.999f}, {0.3f, -1, -0.2f},
                              {0.99f, 0.5f, 1}, {-0.2f, -0.9f, -1}};
    for (int f = 0; f < 6; ++f) {
        const glm::vec3 d = dirs[f];
        const glm::vec3 ndc = ndcOf(faces[f].viewProj, pos + 3.0f * d);
        // Within the face and inside its 2-texel margin (45 degrees maps to 1 - 2 * 2 / 256).
        EXPECT_LE(std::max(std::abs(ndc.x), std::abs(ndc.y)), 1.0f - 4.0f / 256.0f + 1e-5f) << f;
        EXPECT_GT(ndc.z, 0.0f);
        EXPECT_LT(ndc.z, 1.0f);
    }
}

TEST(PointLightMaps, ParaboloidMapsAxisToCentreAndRimToDiscScale) {
    const glm::vec3 pos{0, 2, 0}, axis{0, -1, 0};
    const glm::vec2 range{0.01f, 10.0f};
    const float k = paraboloidDiscScale(512, 4.0f);
    const auto h = paraboloidProjections(pos, axis, range, 512, 4.0f);
    EXPECT_NEAR(k, 1.0f - 8.0f / 512.0f, 1e-6f);
    EXPECT_EQ(h[0].discScale, k);
    const glm::vec3 centre = paraboloidMap(h[0], pos + 2.0f * axis);
    EXPECT_NEAR(glm::length(glm::vec2(centre)), 0.0f, 1e-6f);
    EXPECT_NEAR(centre.z, (2.0f - range.x) / (range.y - range.x), 1e-6f);
    // A direction on the seam (90 degrees from both axes) lands on the rim circle of both halves.
    const glm::vec3 rim = pos + glm::vec3(1.5f, 0.0f, 2.0f);
    for (int i = 0; i < 2; ++i) {
        const glm::vec3 m = paraboloidMap(h[i], rim);
        EXPECT_NEAR(glm::length(glm::vec2(m)), k, 1e-5f);
        EXPECT_NEAR(m.z, (2.5f - range.x) / (range.y - range.x), 1e-6f);
    }
    // 45 degrees: radius k tan(22.5 degrees).
    const glm::vec3 m45 = paraboloidMap(h[0], pos + glm::vec3(1, -1, 0));
    EXPECT_NEAR(glm::length(glm::vec2(m45)), k * std::tan(glm::radians(22.5f)), 1e-5f);
}

TEST(ShadowLayoutTest, LayersPerLightTypeAndMomentLayersOnlyForMomentFilters) {
    ShadowSettings s;
    s.cascades.count = 3;
    s.filter = ShadowFilter::Pcf;
    s.pointMode = PointShadowMode::Paraboloid;
    std::vector<Light> lights(4);
    lights[0].type = LightType::Directional;
    lights[1].type = LightType::Spot;
    lights[1].shadowFilter = ShadowFilter::Vsm;
    lights[2].type = LightType::Point;
    lights[3].type = LightType::Point;
    lights[3].castsShadow = false;
    ShadowLayout layout(s, box(5.0f));
    layout.assign(lights);
    ASSERT_EQ(layout.layers().size(), 3u + 1u + 2u);
    ASSERT_EQ(layout.shadowed().size(), 3u);
    EXPECT_EQ(layout.shadowIndexOf(3), -1);
    EXPECT_EQ(layout.shadowed()[0].kind, uint32_t(SHADOW_KIND_CASCADES));
    EXPECT_EQ(layout.shadowed()[1].filter, ShadowFilter::Vsm);
    EXPECT_EQ(layout.shadowed()[2].kind, uint32_t(SHADOW_KIND_PARABOLOID));
    EXPECT_EQ(layout.shadowed()[2].firstLayer, 4u);
    EXPECT_EQ(layout.momentLayerCount(), 1u);
    layout.update(lights, lookingAt({0, 1, 4}, {0, 0, 0}), 1.0f, 20.0f);
    const auto gpu = layout.gpuLayers();
    EXPECT_EQ(gpu[3].momentLayer, 0u);
    EXPECT_EQ(gpu[0].momentLayer, SHADOW_NO_MOMENTS);
    EXPECT_EQ(gpu[4].projection, uint32_t(SHADOW_PROJ_PARABOLOID));
    EXPECT_EQ(layout.layers()[5].index, 1u);
    EXPECT_GT(gpu[2].splitFar, gpu[1].splitFar);
}

TEST(ShadowCli, FiltersAndPerLightOverrides) {
    EXPECT_EQ(parseShadowFilter("pcss", "--shadow"), ShadowFilter::Pcss);
    EXPECT_EQ(parseShadowFilter("msm", "--shadow"), ShadowFilter::Msm);
    EXPECT_THROW(parseShadowFilter("soft", "--shadow"), std::invalid_argument);
    std::vector<Light> lights(2);
    applyLightFilters({"1=evsm"}, lights);
    EXPECT_EQ(lights[0].shadowFilter, ShadowFilter::Default);
    EXPECT_EQ(lights[1].shadowFilter, ShadowFilter::Evsm);
    for (const char* bad : {"2=pcf", "x=pcf", "1", "1=blur", "=pcf", "99999999999=pcf"})
        EXPECT_THROW(applyLightFilters({bad}, lights), std::invalid_argument) << bad;
    ShadowSettings s;
    s.cascades.count = 9;
    EXPECT_THROW(validate(s), std::invalid_argument);
}
