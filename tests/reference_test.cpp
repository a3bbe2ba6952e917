// The CPU reference path tracer (src/reference) against closed-form and numerically integrated
// answers: Lambertian direct light under each light type (exact: no noise for punctual lights), a
// one-bounce configuration of two perpendicular quads (within a few Monte-Carlo standard errors),
// the rasterizer's visibility rules (single-sided back faces, alpha cut-outs), its camera
// convention, determinism and bad settings. CPU only.
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "gpu_fixture.h"  // double-precision camera rays (no GPU is used here)
#include "reference/path_tracer.h"
#include "scene/builders.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

constexpr double kPi = 3.14159265358979323846;

ReferenceSettings settings(uint32_t w, uint32_t h, uint32_t spp, uint32_t bounces) {
    ReferenceSettings s;
    s.width = w, s.height = h, s.spp = spp, s.bounces = bounces;
    s.threads = 2;
    s.progress = false;
    return s;
}

Light directional(const glm::vec3& dir, float e, const glm::vec3& colour = glm::vec3(1.0f)) {
    Light l;
    l.type = LightType::Directional;
    l.direction = glm::normalize(dir);
    l.intensity = e;
    l.color = colour;
    return l;
}

// Where the centre ray of pixel (x, y) meets the plane y = planeY (the plane scene's camera).
dvec3 planeHit(const Camera& cam, uint32_t w, uint32_t h, uint32_t x, uint32_t y, double planeY = 0.0) {
    const Ray r = cameraRay(cam, w, h, x, y);
    return r.origin + r.dir * *hitHorizontalPlane(r, planeY);
}

// The pixel whose centre ray passes nearest to world point p (plane scene camera: looking down -y,
// image x = world +x, image up = world -z).
std::pair<uint32_t, uint32_t> pixelOf(const Camera& cam, uint32_t w, uint32_t h, const dvec3& p) {
    const double depth = double(cam.eye.y) - p.y, t = std::tan(0.5 * double(cam.fovy));
    const double nx = (p.x - cam.eye.x) / (depth * t * double(w) / h), ny = -(p.z - cam.eye.z) / (depth * t);
    return {uint32_t((nx + 1.0) * 0.5 * w), uint32_t((1.0 - ny) * 0.5 * h)};
}

}  // namespace

TEST(Reference, LambertPlaneUnderDirectionalLightIsExact) {
    Scene scene = makeBuiltinScene("plane");  // albedo 0.5, seen from above
    const double angle = 60.0 * kPi / 180.0;
    const glm::vec3 colour(1.0f, 0.5f, 0.25f);
    scene.lights = {directional({float(std::sin(angle)), -float(std::cos(angle)), 0.0f}, 2.0f, colour)};
    const ReferenceImage img = renderReference(scene, scene.cameras[0], settings(48, 48, 1, 1));
    for (size_t i = 0; i < img.direct.size(); ++i) {
        ASSERT_TRUE(img.covered[i]);
        for (int c = 0; c < 3; ++c) {
            const double expected = 0.5 * 2.0 * colour[c] * std::cos(angle) / kPi;  // albedo E cos / pi
            ASSERT_NEAR(img.direct[i][c], expected, 2e-6 * expected) << "pixel " << i << " channel " << c;
            ASSERT_EQ(img.indirect[i][c], 0.0f) << "a lone plane has nothing to bounce light from";
        }
    }
}

TEST(Reference, SpotAndPointFalloffMatchClosedForm) {
    Scene scene = makeBuiltinScene("plane");
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {1.0f, 4.0f, -2.0f};
    spot.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
    spot.intensity = 50.0f;
    spot.range = 9.0f;
    spot.outerConeAngle = float(40.0 * kPi / 180.0);
    spot.innerConeAngle = float(25.0 * kPi / 180.0);
    Light point;
    point.type = LightType::Point;
    point.position = {-3.0f, 2.0f, 1.0f};
    point.intensity = 20.0f;
    point.range = 7.0f;
    const uint32_t w = 64, h = 48;
    for (const Light& light : {spot, point}) {
        scene.lights = {light};
        const ReferenceImage img = renderReference(scene, scene.cameras[0], settings(w, h, 1, 0));
        size_t lit = 0;
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x) {
                // I / d^2, window (1 - (d/r)^4)^2, cone t^2 (t linear in the cosine), Lambert cos / pi.
                const dvec3 p = planeHit(scene.cameras[0], w, h, x, y);
                const dvec3 v = dvec3(light.position) - p;
                const double d = glm::length(v), cosine = v.y / d;
                const double window = std::pow(std::clamp(1.0 - std::pow(d / light.range, 4.0), 0.0, 1.0), 2.0);
                double cone = 1.0;
                if (light.type == LightType::Spot) {
                    const double co = std::cos(double(light.outerConeAngle));
                    const double ci = std::cos(double(light.innerConeAngle));
                    const double t = std::clamp((glm::dot(-v / d, dvec3(light.direction)) - co) / (ci - co), 0.0, 1.0);
                    cone = t * t;
                }
                const double expected = 0.5 * light.intensity / (d * d) * window * cone * cosine / kPi;
                lit += expected > 0.0;
                ASSERT_NEAR(img.direct[size_t(y) * w + x].x, expected, 1e-4 * expected + 1e-7)
                    << (light.type == LightType::Spot ? "spot" : "point") << " at pixel " << x << "," << y;
            }
        EXPECT_GT(lit, size_t(w * h / 10));
    }
}

namespace {

// Two perpendicular unit quads sharing the edge x = y = 0: a floor (y = 0, x in [0,1], normal +y)
// lit straight from above, and a wall (x = 0, y in [0,1], normal +x) that the light grazes (n.l = 0,
// no direct light). The wall's indirect radiance is rho_w / pi * L_f * integral over the floor of
// cos_p cos_q / r^2 dA, with L_f = rho_f E / pi.
struct TwoQuads {
    glm::vec3 wallAlbedo{0.8f, 0.6f, 0.4f}, floorAlbedo{0.7f, 0.5f, 0.9f};
    float e = 3.0f;
    Scene scene;
    Camera camera;

    TwoQuads() {
        const uint32_t floorMat = addMaterial(scene, floorAlbedo), wallMat = addMaterial(scene, wallAlbedo);
        addQuad(scene, {0, 0, -0.5f}, {0, 0, 1}, {1, 0, 0}, floorMat);
        addQuad(scene, {0, 0, -0.5f}, {0, 1, 0}, {0, 0, 1}, wallMat);
        scene.lights = {directional({0, -1, 0}, e)};
        scene.computeBounds();
        camera.eye = {1.5f, 0.55f, 0.0f};
        camera.target = {0.0f, 0.55f, 0.0f};
        camera.fovy = float(40.0 * kPi / 180.0);
    }

    // Midpoint rule in double precision over n x n cells of the floor.
    double wallIrradianceFactor(const dvec3& p, int n = 600) const {
        double sum = 0.0;
        const double cell = 1.0 / n;
        for (int i = 0; i < n; ++i)
            for (int k = 0; k < n; ++k) {
                const dvec3 q((i + 0.5) * cell, 0.0, -0.5 + (k + 0.5) * cell);
                const dvec3 v = q - p;
                const double r2 = glm::dot(v, v);
                sum += v.x * p.y / (r2 * r2) * cell * cell;  // cos_p = v.x / r, cos_q = p.y / r
            }
        return sum;
    }
};

// Lambert's closed form for a polygon seen from a point with normal n: the integral of
// cos_p cos_q / r^2 over the polygon = pi * F = 1/2 sum_i angle_i * n.normalize(R_i x R_i+1).
double polygonFactor(const dvec3& p, const dvec3& n, const std::vector<dvec3>& poly) {
    double s = 0.0;
    for (size_t i = 0; i < poly.size(); ++i) {
        const dvec3 a = glm::normalize(poly[i] - p), b = glm::normalize(poly[(i + 1) % poly.size()] - p);
        s += std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::dot(n, glm::normalize(glm::cross(a, b)));
    }
    return 0.5 * std::abs(s);
}

}  // namespace

TEST(Reference, OneBounceBetweenPerpendicularQuadsMatchesIntegral) {
    TwoQuads q;
    const uint32_t w = 12, h = 12;
    const ReferenceImage img = renderReference(q.scene, q.camera, settings(w, h, 16384, 1));
    const double floorRadiance = 1.0 / kPi * q.e;  // times the floor albedo
    double zSum = 0.0, relSum = 0.0, worst = 0.0;
    int checked = 0, pixels = 0;
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const Ray r = cameraRay(q.camera, w, h, x, y);
            const dvec3 p = r.origin + r.dir * (-r.origin.x / r.dir.x);  // on the wall's plane x = 0
            const size_t i = size_t(y) * w + x;
            if (p.y < 0.0) {  // the floor: direct light exactly, and nothing comes back from the unlit wall
                for (int c = 0; c < 3; ++c) EXPECT_NEAR(img.direct[i][c], q.floorAlbedo[c] * floorRadiance, 1e-5);
                continue;
            }
            if (p.y < 0.2 || p.y > 0.95 || std::abs(p.z) > 0.45) continue;  // a margin from the edges
            const double g = q.wallIrradianceFactor(p);
            const double closed = polygonFactor(p, {1, 0, 0}, {{0, 0, -0.5}, {0, 0, 0.5}, {1, 0, 0.5}, {1, 0, -0.5}});
            ASSERT_NEAR(g, closed, 1e-4 * closed) << "the test's integration disagrees with Lambert's formula";
            EXPECT_EQ(img.direct[i], glm::vec3(0.0f)) << "the light grazes the wall";
            for (int c = 0; c < 3; ++c) {
                const double expected = q.wallAlbedo[c] / kPi * q.floorAlbedo[c] * floorRadiance * g;
                const double sigma = std::sqrt(double(img.indirectVar[i][c]));
                ASSERT_GT(sigma, 0.0);
                const double z = (img.indirect[i][c] - expected) / sigma;
                EXPECT_LT(std::abs(z), 4.0) << "pixel " << x << "," << y << " channel " << c << ": reference "
                                            << img.indirect[i][c] << ", integral " << expected << ", sigma " << sigma;
                worst = std::max(worst, std::abs(z));
                if (c == 0) zSum += z, relSum += img.indirect[i][c] / expected - 1.0, ++pixels;
                ++checked;
            }
        }
    ASSERT_GE(checked, 30);
    // Independent pixels (the channels of one pixel share their paths: one channel counts): the
    // normalised sum of the z-scores is ~N(0, 1) when the estimate is unbiased.
    EXPECT_LT(std::abs(zSum / std::sqrt(double(pixels))), 4.0);
    std::printf("[ reference ] one bounce, two quads: %d pixels, max |z| %.2f, sum z / sqrt(n) %.2f, mean relative "
                "deviation %+.4f\n", pixels, worst, zSum / std::sqrt(double(pixels)), relSum / pixels);
}

namespace {

// The plane (albedo 0.5) and a 2x2 square at height 1 above its centre (albedo 0.9), lit along
// normalize(1, -1, 0): the square's shadow falls on x in [0, 2].
Scene squareOverPlane(bool facesUp, bool doubleSided, AlphaMode alpha = AlphaMode::Opaque, int texture = -1) {
    Scene s = makeBuiltinScene("plane");
    Material m;
    m.baseColor = glm::vec4(0.9f, 0.9f, 0.9f, 1.0f);
    m.doubleSided = doubleSided;
    m.alphaMode = alpha;
    m.baseColorTexture = texture;
    s.materials.push_back(m);
    const uint32_t mat = uint32_t(s.materials.size() - 1);
    if (facesUp) addQuad(s, {-1, 1, 1}, {2, 0, 0}, {0, 0, -2}, mat);  // u = (x + 1) / 2
    else addQuad(s, {-1, 1, -1}, {2, 0, 0}, {0, 0, 2}, mat);
    s.lights = {directional({1, -1, 0}, 1.0f)};
    s.computeBounds();
    return s;
}

// Radiance (red) at the pixels looking at the square's left half, at the plane in its shadow
// (1.5, 0, 0) and beyond it (2.5, 0, 0). The camera, 15 above the plane, sees the plane past the
// square where |x| > 15/14.
std::array<float, 3> probe(const Scene& s) {
    const uint32_t w = 96, h = 96;
    const ReferenceImage img = renderReference(s, s.cameras[0], settings(w, h, 1, 0));
    std::array<float, 3> out{};
    const dvec3 points[3] = {{-0.5, 1.0, 0.0}, {1.5, 0.0, 0.0}, {2.5, 0.0, 0.0}};
    for (int k = 0; k < 3; ++k) {
        auto [x, y] = pixelOf(s.cameras[0], w, h, points[k]);
        out[k] = img.direct[size_t(y) * w + x].x;
    }
    return out;
}

}  // namespace

TEST(Reference, SingleSidedSurfacesAreInvisibleFromBehindAndCastOnlyFacingTheLight) {
    const float lit = float(std::cos(kPi / 4.0) / kPi);  // E cos / pi, times the albedo
    // Facing up (towards the camera and the light): seen, and casts.
    std::array<float, 3> v = probe(squareOverPlane(true, false));
    EXPECT_NEAR(v[0], 0.9f * lit, 1e-5f);
    EXPECT_EQ(v[1], 0.0f);
    EXPECT_NEAR(v[2], 0.5f * lit, 1e-5f);
    // Facing down, single-sided: the camera sees through it, the light's shadow map would not hold it.
    v = probe(squareOverPlane(false, false));
    EXPECT_NEAR(v[0], 0.5f * lit, 1e-5f) << "the plane under an invisible square";
    EXPECT_NEAR(v[1], 0.5f * lit, 1e-5f) << "no shadow from a back face";
    // Facing down, double-sided: seen (shaded on the side the camera sees) and casts.
    v = probe(squareOverPlane(false, true));
    EXPECT_NEAR(v[0], 0.9f * lit, 1e-5f);
    EXPECT_EQ(v[1], 0.0f);
}

TEST(Reference, AlphaMaskCutsHolesForCameraAndShadowRays) {
    // 8x8 white texture, opaque in its left half (u < 0.5), transparent in its right half.
    auto build = [](AlphaMode mode) {
        Scene s = squareOverPlane(true, false, mode, 0);
        Texture t{8, 8, std::vector<uint8_t>(8 * 8 * 4, 255)};
        for (int y = 0; y < 8; ++y)
            for (int x = 4; x < 8; ++x) t.rgba8[(y * 8 + x) * 4 + 3] = 0;
        s.textures = {t};
        return s;
    };
    const float lit = float(std::cos(kPi / 4.0) / kPi);
    const uint32_t w = 96, h = 96;
    const Scene masked = build(AlphaMode::Mask);
    const ReferenceImage img = renderReference(masked, masked.cameras[0], settings(w, h, 1, 0));
    auto at = [&](const dvec3& p) {
        auto [x, y] = pixelOf(masked.cameras[0], w, h, p);
        return img.direct[size_t(y) * w + x].x;
    };
    EXPECT_NEAR(at({-0.5, 1.0, 0.0}), 0.9f * lit, 1e-3f) << "opaque half seen";
    // Through the hole: the plane at x ~ 0.5, in the opaque half's shadow (dark, not the lit square).
    EXPECT_EQ(at({0.5, 1.0, 0.0}), 0.0f) << "through the hole: the shadowed plane";
    // At x = 1.5 the light passes through the hole.
    EXPECT_NEAR(at({1.5, 0.0, 0.0}), 0.5f * lit, 1e-3f);
    // The same texture on an opaque material ignores alpha.
    const std::array<float, 3> opaque = probe(build(AlphaMode::Opaque));
    EXPECT_EQ(opaque[1], 0.0f);
}

TEST(Reference, CameraConventionMatchesTheRasterizer) {
    // A quad covering only x > 0, z < 0 of the plane scene: image right and image top.
    Scene s = makeBuiltinScene("plane");
    s.vertices.clear(), s.indices.clear(), s.draws.clear();
    addQuad(s, {0, 0, -10}, {0, 0, 10}, {10, 0, 0}, 1);
    const uint32_t w = 40, h = 30;
    const ReferenceImage img = renderReference(s, s.cameras[0], settings(w, h, 1, 0));
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const dvec3 p = planeHit(s.cameras[0], w, h, x, y);
            if (std::abs(p.x) < 1e-3 || std::abs(p.z) < 1e-3 || std::abs(p.x) > 9.99 || std::abs(p.z) > 9.99) continue;
            EXPECT_EQ(img.covered[size_t(y) * w + x], p.x > 0.0 && p.z < 0.0) << "pixel " << x << "," << y;
        }
}

TEST(Reference, DeterministicForASeedWhateverTheThreadCount) {
    const Scene scene = makeBuiltinScene("cornell");
    ReferenceSettings s = settings(32, 24, 4, 2);
    s.threads = 1;
    const ReferenceImage a = renderReference(scene, scene.cameras[0], s);
    s.threads = 3;
    const ReferenceImage b = renderReference(scene, scene.cameras[0], s);
    EXPECT_EQ(a.rgba(ReferenceAov::Final), b.rgba(ReferenceAov::Final));
    s.seed = 2;
    const ReferenceImage c = renderReference(scene, scene.cameras[0], s);
    EXPECT_NE(a.rgba(ReferenceAov::Indirect), c.rgba(ReferenceAov::Indirect));
    EXPECT_EQ(a.rgba(ReferenceAov::Direct), c.rgba(ReferenceAov::Direct)) << "direct light has no noise";
}

TEST(Reference, BadSettingsThrow) {
    const Scene scene = makeBuiltinScene("plane");
    EXPECT_THROW(renderReference(scene, scene.cameras[0], settings(8, 8, 0, 1)), std::invalid_argument);
    EXPECT_THROW(renderReference(scene, scene.cameras[0], settings(8, 8, 1, kMaxReferenceBounces + 1)),
                 std::invalid_argument);
    EXPECT_THROW(renderReference(scene, scene.cameras[0], settings(0, 8, 1, 1)), std::invalid_argument);
    EXPECT_THROW(parseReferenceAov("albedo"), std::invalid_argument);
}
