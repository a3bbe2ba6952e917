#include "app/ghosting.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>

#include "app/response.h"
#include "frame/frame_options.h"
#include "lighting/lighting_technique.h"

namespace penumbra {
namespace {

// The eye distance of every pixel of the frame `r` rendered last (+inf where no surface).
std::vector<float> eyeDistances(Renderer& r) {
    const uint32_t w = r.settings().width, h = r.settings().height;
    const std::vector<uint8_t> depth = r.commands().readImage(r.find<CameraTechnique>()->gbuffer().depth, 4);
    const gpu::FrameUniforms& u = r.frameUniforms();
    const glm::vec3 eye(u.eye);
    std::vector<float> out(size_t(w) * h, std::numeric_limits<float>::infinity());
    for (size_t i = 0; i < out.size(); ++i) {
        float d;
        std::memcpy(&d, depth.data() + i * 4, 4);
        if (d >= 1.0f) continue;
        const glm::vec4 p = u.invViewProj * glm::vec4((float(i % w) + 0.5f) / float(w) * 2 - 1,
                                                      (float(i / w) + 0.5f) / float(h) * 2 - 1, d, 1.0f);
        out[i] = glm::length(glm::vec3(p) / p.w - eye);
    }
    return out;
}

// The converged still image of the pose at time t: a fresh history, `settle` frames.
std::vector<float> convergedIndirect(vk::Context& ctx, GpuScene& scene, const RenderSettings& s,
                                     const SceneMotion& motion, double t, int settle) {
    Renderer still(ctx, scene, s, 1);
    const FrameInputs in = frameInputs(motion, t);
    for (int i = 0; i < settle; ++i) still.render(in);
    return luminanceOf(still.readHdr());
}

}  // namespace

std::vector<size_t> disoccludedPixels(const std::vector<float>& before, const std::vector<float>& now) {
    std::vector<size_t> out;
    for (size_t i = 0; i < before.size() && i < now.size(); ++i)
        if (std::isfinite(before[i]) && before[i] < 0.97f * now[i]) out.push_back(i);
    return out;
}

nlohmann::json measureGhosting(vk::Context& ctx, GpuScene& scene, const RenderSettings& settings,
                               const SceneMotion& motion, const GhostingRun& run) {
    Renderer moving(ctx, scene, settings, 1);
    std::vector<std::vector<float>> distances;  // the last three frames'
    nlohmann::json instants = nlohmann::json::array();
    double errorSum = 0.0, referenceSum = 0.0;
    size_t pixels = 0, far = 0;
    for (int i = 0; i < run.warmup + run.frames; ++i) {
        const double t = run.start + i / run.fps;
        moving.render(frameInputs(motion, t));
        distances.push_back(eyeDistances(moving));
        if (distances.size() > 3) distances.erase(distances.begin());
        if (i < run.warmup || distances.size() < 3) continue;
        const std::vector<size_t> mask = disoccludedPixels(distances.front(), distances.back());
        const std::vector<float> now = luminanceOf(moving.readHdr());
        const std::vector<float> still = convergedIndirect(ctx, scene, settings, motion, t, run.settle);
        double e = 0.0, ref = 0.0;
        size_t off = 0;
        for (size_t p : mask) {
            const double d = std::abs(double(now[p]) - double(still[p]));
            e += d, ref += still[p];
            off += d > 0.1 * still[p];
        }
        instants.push_back({{"time", t}, {"pixels", mask.size()}, {"rel_l1", ref > 0.0 ? e / ref : 0.0},
                            {"share_beyond_10_percent", mask.empty() ? 0.0 : double(off) / double(mask.size())}});
        errorSum += e, referenceSum += ref, pixels += mask.size(), far += off;
    }
    return {{"instants", instants}, {"pixels", pixels}, {"rel_l1", referenceSum > 0.0 ? errorSum / referenceSum : 0.0},
            {"share_beyond_10_percent", pixels ? double(far) / double(pixels) : 0.0}};
}

}  // namespace penumbra
