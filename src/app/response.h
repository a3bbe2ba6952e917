// `penumbra stability --change sun:DEG|off|on`: how fast the temporal GI follows a sudden change of
// the light. After `settle` still frames with the old light (I_old), the change, and `settle` more
// (I_new), each pixel's response after k frames is r_k = (I_k - I_old) / (I_new - I_old), over the
// pixels whose indirect light changes by more than 5% of the image's mean.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/renderer.h"

namespace penumbra {

struct LightChange {
    enum class Kind { SunTurn, Off, On } kind = Kind::SunTurn;
    float degrees = 0.0f;  // SunTurn: every directional light's direction turned by this angle
};
// "sun:DEG", "off" (the first light goes out) or "on" (it comes on). Throws std::invalid_argument.
LightChange parseLightChange(const std::string& text);
// The lights before and after the change.
std::pair<std::vector<Light>, std::vector<Light>> changedLights(const std::vector<Light>& lights, const LightChange& c);

// The Rec. 709 luminance of every pixel of an RGBA image.
std::vector<float> luminanceOf(const std::vector<float>& rgba);

// The response figures of luminance images: per k, the median and the 5th percentile of r_k.
nlohmann::json responseFigures(const std::vector<float>& before, const std::vector<float>& after,
                               const std::vector<std::vector<float>>& frames);

// Renders the change with `renderer` (its AOV the indirect light) and returns responseFigures' JSON
// for r_1 ... r_frames.
nlohmann::json measureResponse(Renderer& renderer, const Camera& camera, const LightChange& change,
                               const std::vector<Light>& lights, int settle, int frames);

}  // namespace penumbra
