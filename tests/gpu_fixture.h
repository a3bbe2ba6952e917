// Shared fixture of the GPU tests: a lavapipe context with the Khronos validation layer on, a helper
// that renders a Scene to a float image, and double-precision camera rays for analytic references.
// Every test built on GpuTest fails if the validation layer reported anything while it ran.
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "renderer/renderer.h"
#include "test_renderer.h"
#include "scene/scene.h"
#include "vk/context.h"

namespace penumbra::test {

// An RGBA32F image as Renderer::readHdr returns it: row-major, top row first.
struct FloatImage {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;
    float at(uint32_t x, uint32_t y, int channel = 0) const { return rgba[(size_t(y) * width + x) * 4 + channel]; }
};

struct RenderResult {
    FloatImage image;
    std::vector<vk::ScopeTiming> timings;
    std::vector<std::string> warnings;
};

class GpuTest : public ::testing::Test {
protected:
    void SetUp() override {
        vk::ContextOptions options;
        options.validate = true;
        options.syncValidation = true;  // hazards between passes and across frames in flight
        options.quiet = true;  // the log is printed by TearDown when something was reported
        ctx_ = std::make_unique<vk::Context>(options);
    }

    void TearDown() override {
        if (!ctx_) return;
        ctx_->waitIdle();
        std::string log;
        for (const std::string& m : ctx_->validationLog()) log += m + "\n";
        EXPECT_EQ(ctx_->validationMessages(), 0u) << "validation layer reported:\n" << log;
        ctx_.reset();
    }

    vk::Context& ctx() { return *ctx_; }

    // Renders `scene` once from `camera` and reads the AOV back as linear floats. The Renderer lives
    // only inside this call, so its Vulkan objects are destroyed before TearDown counts messages.
    RenderResult render(const Scene& scene, const Camera& camera, uint32_t width, uint32_t height, Aov aov,
                        const std::optional<ShadowSettings>& shadow = std::nullopt) {
        RenderSettings settings;
        settings.width = width;
        settings.height = height;
        settings.aov = aov;
        if (shadow) settings.shadow = *shadow;
        TestRenderer renderer(ctx(), scene, settings);
        renderer.setPassScopes(true);  // the result's per-pass timings
        renderer.render(camera);
        RenderResult out;
        out.image = {width, height, renderer.readHdr()};
        out.timings = renderer.timings();
        out.warnings = renderer.warnings();
        EXPECT_EQ(out.image.rgba.size(), size_t(width) * height * 4);
        return out;
    }

    FloatImage renderImage(const Scene& scene, const Camera& camera, uint32_t width, uint32_t height, Aov aov,
                           const std::optional<ShadowSettings>& shadow = std::nullopt) {
        return render(scene, camera, width, height, aov, shadow).image;
    }

private:
    std::unique_ptr<vk::Context> ctx_;
};

// World positions of the last frame's G-buffer pixels, reconstructed in double precision from the
// read-back depth (nullopt where no surface was drawn). Row-major, top row first.
inline std::vector<std::optional<glm::dvec3>> gbufferWorldPositions(TestRenderer& r) {
    const uint32_t w = r.settings().width, h = r.settings().height;
    const std::vector<uint8_t> depth = r.commands().readImage(r.gbuffer().depth, 4);
    const glm::dmat4 inv(r.frameUniforms().invViewProj);
    std::vector<std::optional<glm::dvec3>> out(size_t(w) * h);
    for (size_t i = 0; i < out.size(); ++i) {
        float d;
        std::memcpy(&d, depth.data() + i * 4, 4);
        if (d >= 1.0f) continue;
        const glm::dvec4 p = inv * glm::dvec4((double(i % w) + 0.5) / w * 2.0 - 1.0,
                                              (double(i / w) + 0.5) / h * 2.0 - 1.0, d, 1.0);
        out[i] = glm::dvec3(p) / p.w;
    }
    return out;
}

// ---- Analytic helpers (double precision, independent of the renderer's matrices) ----

using dvec3 = glm::dvec3;

struct Ray {
    dvec3 origin;
    dvec3 dir;  // unit length
};

// The ray through the centre of pixel (px, py) (py = 0 is the top row) of an ideal pinhole camera:
// vertical field of view camera.fovy, aspect width/height, image up = the camera's up vector.
inline Ray cameraRay(const Camera& camera, uint32_t width, uint32_t height, uint32_t px, uint32_t py) {
    const dvec3 eye(camera.eye), target(camera.target), up(camera.up);
    const dvec3 f = glm::normalize(target - eye);
    const dvec3 r = glm::normalize(glm::cross(f, up));
    const dvec3 u = glm::cross(r, f);
    const double t = std::tan(0.5 * double(camera.fovy));
    const double aspect = double(width) / double(height);
    const double sx = ((px + 0.5) / width * 2.0 - 1.0) * t * aspect;
    const double sy = (1.0 - (py + 0.5) / height * 2.0) * t;
    return {eye, glm::normalize(f + sx * r + sy * u)};
}

// Distance along the ray to the horizontal plane y = planeY, or nullopt when it does not hit it ahead.
inline std::optional<double> hitHorizontalPlane(const Ray& ray, double planeY) {
    if (std::abs(ray.dir.y) < 1e-12) return std::nullopt;
    const double t = (planeY - ray.origin.y) / ray.dir.y;
    if (t <= 0.0) return std::nullopt;
    return t;
}

// Axis-aligned square in a horizontal plane: |x - cx| <= half and |z - cz| <= half at y = y.
struct HorizontalSquare {
    double cx, y, cz, half;

    bool contains(const dvec3& p) const { return std::abs(p.x - cx) <= half && std::abs(p.z - cz) <= half; }

    // Unsigned distance (in the square's plane) from (p.x, p.z) to the square's boundary.
    double boundaryDistance(const dvec3& p) const {
        const double dx = std::abs(p.x - cx) - half, dz = std::abs(p.z - cz) - half;
        if (dx <= 0.0 && dz <= 0.0) return -std::max(dx, dz);  // inside: distance to the nearest edge
        return std::hypot(std::max(dx, 0.0), std::max(dz, 0.0));
    }
};

// sRGB transfer function (decode), as the G-buffer's R8G8B8A8_SRGB attachment applies it on read.
inline double srgbToLinear(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

}  // namespace penumbra::test
