// Unit tests of the math penumbra writes itself: light-space projections, camera matrices, CLI parsing.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "core/light_space.h"
#include "frame/input_parse.h"

using namespace penumbra;

namespace {

glm::vec3 project(const glm::mat4& m, const glm::vec3& p) {
    glm::vec4 c = m * glm::vec4(p, 1.0f);
    return glm::vec3(c) / c.w;
}

Bounds unitBox() {
    Bounds b;
    b.extend({-1, -1, -1});
    b.extend({1, 1, 1});
    return b;
}

}  // namespace

TEST(LightSpace, DirectionalCoversBoundsInsideClipVolume) {
    Bounds b = unitBox();
    LightProjection p = directionalProjection(glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f)), b, 1024);
    for (int i = 0; i < 8; ++i) {
        glm::vec3 corner{(i & 1) ? 1.f : -1.f, (i & 2) ? 1.f : -1.f, (i & 4) ? 1.f : -1.f};
        glm::vec3 ndc = project(p.viewProj, corner);
        EXPECT_LE(std::abs(ndc.x), 1.0f);
        EXPECT_LE(std::abs(ndc.y), 1.0f);
        EXPECT_GE(ndc.z, 0.0f);
        EXPECT_LE(ndc.z, 1.0f);
    }
    EXPECT_FALSE(p.perspective);
    EXPECT_NEAR(p.texelSize, 2.0f * std::sqrt(3.0f) / 1024.0f, 1e-6f);
}

TEST(LightSpace, DirectionalDepthIncreasesAlongLight) {
    glm::vec3 dir{0, -1, 0};
    LightProjection p = directionalProjection(dir, unitBox(), 512);
    EXPECT_LT(project(p.viewProj, {0, 1, 0}).z, project(p.viewProj, {0, -1, 0}).z);
    // Points along the same light ray land on the same texel.
    glm::vec3 a = project(p.viewProj, {0.3f, 0.5f, -0.2f}), b = project(p.viewProj, {0.3f, -0.5f, -0.2f});
    EXPECT_NEAR(a.x, b.x, 1e-5f);
    EXPECT_NEAR(a.y, b.y, 1e-5f);
}

TEST(LightSpace, SpotConeEdgeMapsToMapEdge) {
    Light l;
    l.type = LightType::Spot;
    l.position = {0, 2, 0};
    l.direction = {0, -1, 0};
    l.outerConeAngle = glm::radians(30.0f);
    LightProjection p = spotProjection(l, unitBox(), 1000);
    EXPECT_TRUE(p.perspective);
    // A point on the cone's edge, 2 units below the light.
    glm::vec3 edge{2.0f * std::tan(l.outerConeAngle), 0.0f, 0.0f};
    glm::vec3 ndc = project(p.viewProj, edge);
    EXPECT_NEAR(std::max(std::abs(ndc.x), std::abs(ndc.y)), 1.0f, 1e-4f);
    EXPECT_NEAR(p.texelSize, 2.0f * std::tan(l.outerConeAngle) / 1000.0f, 1e-7f);
    glm::vec3 center = project(p.viewProj, {0, -1, 0});
    EXPECT_NEAR(center.x, 0.0f, 1e-5f);
    EXPECT_GT(center.z, 0.0f);
    EXPECT_LT(center.z, 1.0f);
}

TEST(Camera, TargetProjectsToImageCentreAndUpIsUp) {
    Camera c;
    c.eye = {0, 1, 5};
    c.target = {0, 1, 0};
    glm::mat4 vp = cameraViewProj(c, 16.0f / 9.0f, 100.0f);
    glm::vec3 centre = project(vp, c.target);
    EXPECT_NEAR(centre.x, 0.0f, 1e-6f);
    EXPECT_NEAR(centre.y, 0.0f, 1e-6f);
    // Vulkan NDC: +y is down the image, so a point above the target has negative y.
    EXPECT_LT(project(vp, {0, 2, 0}).y, 0.0f);
    EXPECT_GT(project(vp, {1, 1, 0}).x, 0.0f);
}

TEST(CliParse, CameraAndLights) {
    Camera c = parseCamera("0,1,5,0,1,0,0,1,0,45");
    EXPECT_FLOAT_EQ(c.eye.z, 5.0f);
    EXPECT_NEAR(c.fovy, glm::radians(45.0f), 1e-6f);
    Light d = parseLight("directional,0,-2,0,3");
    EXPECT_EQ(d.type, LightType::Directional);
    EXPECT_NEAR(d.direction.y, -1.0f, 1e-6f);
    EXPECT_FLOAT_EQ(d.intensity, 3.0f);
    Light s = parseLight("spot,0,2,0,0,-1,0,5,40,30");
    EXPECT_EQ(s.type, LightType::Spot);
    EXPECT_NEAR(s.outerConeAngle, glm::radians(40.0f), 1e-6f);
    EXPECT_EQ(parseLight("point,1,2,3,4").type, LightType::Point);
    EXPECT_EQ(parseAov("shadow"), Aov::Shadow);
}

TEST(CliParse, RejectsBadValues) {
    EXPECT_THROW(parseCamera("1,2,3"), std::invalid_argument);
    EXPECT_THROW(parseCamera("0,0,0,0,0,0,0,1,0,45"), std::invalid_argument);
    EXPECT_THROW(parseCamera("0,1,5,0,1,0,0,1,0,x"), std::invalid_argument);
    EXPECT_THROW(parseCamera("0,1,5,0,1,0,0,1,0,190"), std::invalid_argument);
    EXPECT_THROW(parseLight("laser,1,2,3"), std::invalid_argument);
    EXPECT_THROW(parseLight("directional,0,0,0,1"), std::invalid_argument);
    EXPECT_THROW(parseLight("point,1,2,3,-4"), std::invalid_argument);
    EXPECT_THROW(parseAov("beauty"), std::invalid_argument);
}
