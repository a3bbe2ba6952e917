// Shared by the RSM tests (rsm_test.cpp, rsm_visibility_test.cpp): a rendered frame's receivers and
// VPLs read back in double precision, the brute-force sum over them, and a fixture that renders cornell.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstring>

#include "gpu_fixture.h"
#include "readback.h"
#include "scene/builders.h"

namespace penumbra::test::rsm {

inline constexpr double kPi = 3.14159265358979323846;

inline dvec3 unproject(const glm::dmat4& inv, double u, double v, double depth) {
    glm::dvec4 p = inv * glm::dvec4(u * 2.0 - 1.0, v * 2.0 - 1.0, depth, 1.0);
    return dvec3(p) / p.w;
}

inline dvec3 octDecode(double ex, double ey) {
    dvec3 n(ex, ey, 1.0 - std::abs(ex) - std::abs(ey));
    const double t = std::max(-n.z, 0.0);
    n.x += n.x >= 0.0 ? -t : t;
    n.y += n.y >= 0.0 ? -t : t;
    return glm::normalize(n);
}

struct Vpl {
    dvec3 position, normal, flux;
    double footprint;  // squared world size: the lower clamp of d^2
};

// Everything read back from one rendered frame: receivers (G-buffer) and VPLs (RSM).
struct Frame {
    uint32_t width, height;
    std::vector<dvec3> position, normal;  // per pixel; normal zero where there is no surface
    std::vector<Vpl> vpls;
    std::vector<glm::dvec3> gpuIrradiance;
};

inline Frame readFrame(TestRenderer& r) {
    Frame f{r.settings().width, r.settings().height, {}, {}, {}, {}};
    vk::CommandContext& cmd = r.commands();
    const gpu::FrameUniforms& fu = r.frameUniforms();
    const auto world = gbufferWorldPositions(r);
    auto normal = cmd.readImage(r.gbuffer().normal, 8);
    auto irr = cmd.readImage(r.rsmGather()->irradiance(), 16);
    const size_t n = size_t(f.width) * f.height;
    f.position.resize(n);
    f.normal.resize(n);
    f.gpuIrradiance.resize(n);
    for (size_t i = 0; i < n; ++i) {
        f.gpuIrradiance[i] = {f32(irr, i * 4), f32(irr, i * 4 + 1), f32(irr, i * 4 + 2)};
        if (!world[i]) continue;
        f.position[i] = *world[i];
        dvec3 nn = glm::normalize(dvec3(half(normal, i * 4), half(normal, i * 4 + 1), half(normal, i * 4 + 2)));
        if (glm::dot(nn, dvec3(fu.eye) - f.position[i]) < 0.0) nn = -nn;
        f.normal[i] = nn;
    }
    RsmPass& rsm = *r.rsm();
    const uint32_t res = rsm.settings().resolution;
    const auto* table = rsm.layerTable().as<gpu::GpuRsmLayer>();
    for (uint32_t layer = 0; layer < rsm.layerCount(); ++layer) {
        auto rd = cmd.readImage(rsm.depth(), 4, layer);
        auto rn = cmd.readImage(rsm.normal(), 4, layer);
        auto rf = cmd.readImage(rsm.flux(), 8, layer);
        const glm::dmat4 inv(table[layer].invViewProj), vp(table[layer].viewProj);
        for (uint32_t t = 0; t < res * res; ++t) {
            const double d = f32(rd, t);
            if (d >= 1.0) continue;
            int16_t e[2];
            std::memcpy(e, rn.data() + t * 4, 4);
            Vpl vpl;
            vpl.position = unproject(inv, (t % res + 0.5) / res, (t / res + 0.5) / res, d);
            vpl.normal = octDecode(std::max(e[0] / 32767.0, -1.0), std::max(e[1] / 32767.0, -1.0));
            vpl.flux = {half(rf, t * 4), half(rf, t * 4 + 1), half(rf, t * 4 + 2)};
            double texel = table[layer].texelSize;
            if (table[layer].perspective != 0u) texel *= std::abs((vp * glm::dvec4(vpl.position, 1.0)).w);
            vpl.footprint = texel * texel;
            f.vpls.push_back(vpl);
        }
    }
    return f;
}

// E(x, n) = sum_p phi_p / pi * max(0, n_p.(x - x_p)) max(0, n.(x_p - x)) / max(d^2, footprint_p)^2
inline dvec3 bruteForce(const Frame& f, size_t pixel) {
    dvec3 e(0.0);
    const dvec3 x = f.position[pixel], n = f.normal[pixel];
    for (const Vpl& p : f.vpls) {
        const dvec3 v = x - p.position;
        const double d2 = std::max(glm::dot(v, v), p.footprint);
        e += p.flux * (std::max(glm::dot(p.normal, v), 0.0) * std::max(glm::dot(n, -v), 0.0) / (d2 * d2) / kPi);
    }
    return e;
}

inline double luminance(const dvec3& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

// The indirect light of RSM GI alone, every RSM texel gathered: the exact sum a brute force checks.
inline RenderSettings exactIndirect(uint32_t width, uint32_t height, uint32_t rsmResolution) {
    RenderSettings s;
    s.width = width;
    s.height = height;
    s.aov = Aov::Indirect;
    s.gi = GiMode::Rsm;
    s.rsm.resolution = rsmResolution;
    s.rsm.mode = RsmMode::AllTexels;
    s.rsm.visibility = RsmVisibility::None;  // the brute force's sum: every VPL the receiver faces
    return s;
}

class RsmTest : public GpuTest {
protected:
    // Renders cornell with RSM GI and hands the frame to `check` while the renderer is alive.
    template <class Check>
    void renderCornell(uint32_t w, uint32_t h, const RsmSettings& rsm, Aov aov, Check check) {
        Scene scene = makeBuiltinScene("cornell");
        RenderSettings s;
        s.width = w;
        s.height = h;
        s.aov = aov;
        s.gi = GiMode::Rsm;
        s.rsm = rsm;
        TestRenderer r(ctx(), scene, s);
        r.render(scene.cameras[0]);
        check(r);
    }
};

// Relative RMS error of a per-pixel irradiance against a reference, over pixels with a surface.
inline double relativeRms(const Frame& f, const std::vector<dvec3>& reference, const std::vector<glm::dvec3>& value) {
    double err = 0.0, ref = 0.0;
    for (size_t i = 0; i < reference.size(); ++i) {
        if (f.normal[i] == dvec3(0.0)) continue;
        err += std::pow(luminance(value[i] - reference[i]), 2);
        ref += std::pow(luminance(reference[i]), 2);
    }
    return std::sqrt(err / ref);
}

}  // namespace penumbra::test::rsm
