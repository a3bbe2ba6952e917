// `penumbra stability --ghosting`: how much of a moving object's old light the temporal GI keeps
// where the object has just left. At each measured frame of the scene's animation, the pixels that
// the nearer geometry covered two frames earlier and no longer covers are compared with the
// converged still image of that instant (a fresh renderer, `settle` frames of the frozen pose).
#pragma once
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/renderer.h"
#include "scene/motion.h"

namespace penumbra {

struct GhostingRun {
    double start = 0.0;  // scene time of the first warm-up frame
    double fps = 30.0;
    int warmup = 32;     // animated frames before the first measured one (the history in motion)
    int frames = 4;      // measured instants
    int settle = 64;     // still frames of each instant's converged image
};

// Per instant and over all: the disoccluded pixels, their indirect light's relative L1 error against
// the converged image, and the share of them more than 10% away from it. `settings` renders the
// indirect AOV.
nlohmann::json measureGhosting(vk::Context& ctx, GpuScene& scene, const RenderSettings& settings,
                               const SceneMotion& motion, const GhostingRun& run);

// The disoccluded pixels: nearer than now by more than 3% of the eye distance two frames earlier
// (`before` and `now` are eye distances, +inf where no surface).
std::vector<size_t> disoccludedPixels(const std::vector<float>& before, const std::vector<float>& now);

}  // namespace penumbra
