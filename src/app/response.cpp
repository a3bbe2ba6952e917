#include "app/response.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/gtc/quaternion.hpp>

namespace penumbra {
namespace {

double quantile(std::vector<double> v, double q) {
    if (v.empty()) return std::nan("");
    const size_t k = std::min(v.size() - 1, size_t(q * double(v.size() - 1) + 0.5));
    std::nth_element(v.begin(), v.begin() + ptrdiff_t(k), v.end());
    return v[k];
}

}  // namespace

std::vector<float> luminanceOf(const std::vector<float>& rgba) {
    std::vector<float> out(rgba.size() / 4);
    for (size_t i = 0; i < out.size(); ++i)
        out[i] = 0.2126f * rgba[4 * i] + 0.7152f * rgba[4 * i + 1] + 0.0722f * rgba[4 * i + 2];
    return out;
}

LightChange parseLightChange(const std::string& text) {
    if (text == "off") return {LightChange::Kind::Off, 0.0f};
    if (text == "on") return {LightChange::Kind::On, 0.0f};
    if (text.rfind("sun:", 0) == 0) {
        size_t used = 0;
        float degrees = 0.0f;
        try {
            degrees = std::stof(text.substr(4), &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == text.size() - 4 && std::isfinite(degrees) && degrees != 0.0f && std::abs(degrees) <= 180.0f)
            return {LightChange::Kind::SunTurn, degrees};
    }
    throw std::invalid_argument("expected sun:DEG (0 < |DEG| <= 180), off or on");
}

std::pair<std::vector<Light>, std::vector<Light>> changedLights(const std::vector<Light>& lights, const LightChange& c) {
    if (lights.empty()) throw std::invalid_argument("the scene has no light to change");
    std::vector<Light> before = lights, after = lights;
    if (c.kind == LightChange::Kind::Off) after[0].intensity = 0.0f;
    if (c.kind == LightChange::Kind::On) before[0].intensity = 0.0f;
    if (c.kind == LightChange::Kind::SunTurn) {
        bool any = false;
        for (Light& l : after) {
            if (l.type != LightType::Directional) continue;
            // About the horizontal axis across the sun's direction: its direction turns by DEG (its
            // elevation changes), where a turn about the vertical would move a high sun by less.
            glm::vec3 axis = glm::cross(l.direction, glm::vec3(0, 1, 0));
            axis = glm::length(axis) > 1e-6f ? glm::normalize(axis) : glm::vec3(1, 0, 0);
            l.direction = glm::angleAxis(glm::radians(c.degrees), axis) * l.direction;
            any = true;
        }
        if (!any) throw std::invalid_argument("the scene has no directional light to turn");
    }
    return {before, after};
}

nlohmann::json responseFigures(const std::vector<float>& before, const std::vector<float>& after,
                               const std::vector<std::vector<float>>& frames) {
    double mean = 0.0;
    for (float v : before) mean += v;
    mean /= double(std::max<size_t>(before.size(), 1));
    std::vector<size_t> changed;
    for (size_t i = 0; i < before.size(); ++i)
        if (std::abs(after[i] - before[i]) > 0.05 * mean) changed.push_back(i);
    nlohmann::json out{{"pixels_changed", changed.size()}, {"image_mean_before", mean}, {"r", nlohmann::json::array()}};
    for (size_t k = 0; k < frames.size(); ++k) {
        std::vector<double> r;
        r.reserve(changed.size());
        for (size_t i : changed) r.push_back((frames[k][i] - before[i]) / double(after[i] - before[i]));
        out["r"].push_back({{"k", k + 1}, {"median", quantile(r, 0.5)}, {"p05", quantile(r, 0.05)}});
    }
    return out;
}

nlohmann::json measureResponse(Renderer& renderer, const Camera& camera, const LightChange& change,
                               const std::vector<Light>& lights, int settle, int frames) {
    const auto [before, after] = changedLights(lights, change);
    for (int i = 0; i < settle; ++i) renderer.render(FrameInputs{camera, before});
    const std::vector<float> old = luminanceOf(renderer.readHdr());
    std::vector<std::vector<float>> response;
    for (int i = 0; i < std::max(settle, frames); ++i) {
        renderer.render(FrameInputs{camera, after});
        if (i < frames) response.push_back(luminanceOf(renderer.readHdr()));
    }
    return responseFigures(old, luminanceOf(renderer.readHdr()), response);
}

}  // namespace penumbra
