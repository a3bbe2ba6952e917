#include "temporal_gi/temporal_gi_technique.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "core/gpu_scene.h"

namespace penumbra {
namespace {

// A light whose radiance changes by this share restarts the history as a turn of resetAngle does.
constexpr float kResetRadianceChange = 0.5f;
// A light that moves by this share of the scene's size counts as a turn of one radian.
constexpr float kMoveAsRadian = 0.25f;
// A camera that turns or moves this much in a frame cut to another view.
constexpr float kCutDegrees = 30.0f;
constexpr float kCutMove = 0.2f;

// atan2 of the sine and cosine: exact for small angles, where acos of a float dot is off by 0.03 degrees.
float degreesBetween(glm::vec3 a, glm::vec3 b) {
    a = glm::normalize(a), b = glm::normalize(b);
    return glm::degrees(std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)));
}

float luminance(glm::vec3 c) { return glm::dot(c, glm::vec3(0.2126f, 0.7152f, 0.0722f)); }

}  // namespace

float lightChangeWeight(const std::vector<Light>& before, const std::vector<Light>& now, float sceneSize,
                        float resetAngle) {
    if (before.size() != now.size()) return 1.0f;
    float change = 0.0f;  // in units of a restart
    for (size_t i = 0; i < now.size(); ++i) {
        const Light &a = before[i], &b = now[i];
        if (a.type != b.type) return 1.0f;
        float turn = 0.0f;  // degrees
        if (b.type != LightType::Point) turn = degreesBetween(a.direction, b.direction);
        if (b.type != LightType::Directional)
            turn = std::max(turn, glm::degrees(glm::length(b.position - a.position) / (kMoveAsRadian * sceneSize)));
        if (b.type == LightType::Spot)
            turn = std::max(turn, glm::degrees(std::abs(b.outerConeAngle - a.outerConeAngle)));
        const float la = luminance(a.color) * a.intensity, lb = luminance(b.color) * b.intensity;
        const float radiance = std::abs(lb - la) / std::max({la, lb, 1e-20f});
        change = std::max({change, turn / resetAngle, radiance / kResetRadianceChange});
    }
    return std::min(change * change, 1.0f);
}

bool cameraCut(const Camera& before, const Camera& now, float sceneSize) {
    return degreesBetween(before.target - before.eye, now.target - now.eye) > kCutDegrees ||
           glm::length(now.eye - before.eye) > kCutMove * sceneSize || before.fovy != now.fovy;
}

TemporalGiTechnique::TemporalGiTechnique(const TechniqueBuild& b, const TemporalGiSettings& s)
    : board_(b.board), settings_(s),
      sceneSize_(std::max(glm::length(b.scene.scene().bounds.max - b.scene.scene().bounds.min), 1e-6f)),
      sum_(b.alloc, b.core.width, b.core.height), history_(b.alloc, b.core.width, b.core.height),
      filter_(b.alloc, b.core.width, b.core.height) {
    b.board.put(names::kGiAccumulation, &accumulation_, this);
}

TemporalGiTechnique::~TemporalGiTechnique() { board_.dropOwner(this); }

uint64_t TemporalGiTechnique::bytes(uint64_t width, uint64_t height) {
    return GiHistory::bytes(width, height) + GiFilter::bytes(width, height);
}

void TemporalGiTechnique::setSettings(const TemporalGiSettings& s, const std::string& estimator) {
    settings_ = s;
    if (estimator != estimator_) restart_ = true;
    estimator_ = estimator;
}

void TemporalGiTechnique::update(const FrameContext& f) {
    changeWeight_ = restart_ ? 1.0f : lightChangeWeight(lastLights_, f.lights, sceneSize_, settings_.resetAngle);
    if (!restart_ && cameraCut(*lastCamera_, f.camera, sceneSize_)) changeWeight_ = 1.0f;
    if (changeWeight_ >= 1.0f) history_.reset();
    restart_ = false;
    lastCamera_ = f.camera;
    lastLights_ = f.lights;
    ++frames_;
    accumulation_.accumulating = changeWeight_ < 1.0f;
    accumulation_.frameSeed = accumulation_.accumulating ? std::max(frames_, 1u) : 0u;
}

void TemporalGiTechnique::addPasses(const FrameContext& f) {
    const ImageHandle now = sum_.addTo(f.graph);
    if (!now) {  // no GI this frame: nothing to accumulate, and nothing to keep
        history_.release();
        filter_.release();
        return;
    }
    GiBlend blend{settings_.minWeight, changeWeight_};
    const GiChange* change = f.board.get(names::kGiChange);
    if (change && f.graph.has(names::kGiChangeImage)) {
        blend.change = f.graph.image(names::kGiChangeImage);
        blend.changePixels = change->pixels;
        blend.lagTolerance = change->lagTolerance;
    }
    const GiHistoryImages history = history_.addTo(f.graph, now, blend);
    const ImageHandle out = settings_.filterIterations == 0
                                ? history.color
                                : filter_.addTo(f.graph, history, settings_.filterIterations, settings_.luminanceSigma);
    f.graph.publish(names::kIrradiance, out);
    f.graph.setContributions(names::kIrradianceContribution, {out});
}

}  // namespace penumbra
