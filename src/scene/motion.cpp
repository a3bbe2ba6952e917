#include "scene/motion.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <glm/gtc/constants.hpp>

namespace penumbra {
namespace {

std::vector<std::string> split(const std::string& s, char sep) {
    std::vector<std::string> out;
    std::stringstream in(s);
    std::string part;
    while (std::getline(in, part, sep)) out.push_back(part);
    return out;
}

std::vector<float> numbers(const std::string& s) {
    std::vector<float> out;
    for (const std::string& p : split(s, ',')) {
        size_t used = 0;
        float v = 0.0f;
        try {
            v = std::stof(p, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || used != p.size() || !std::isfinite(v))
            throw std::invalid_argument(fmt::format("'{}' is not a finite number", p));
        out.push_back(v);
    }
    return out;
}

// "T,X,Y,Z;T,X,Y,Z;..." (`extra` more numbers per key go to `second`).
void parseKeys(const std::string& text, Keyframes& first, Keyframes* second) {
    const size_t per = second ? 7 : 4;
    for (const std::string& key : split(text, ';')) {
        const std::vector<float> v = numbers(key);
        if (v.size() != per)
            throw std::invalid_argument(fmt::format("each key is {} numbers (T,{}), got '{}'", per,
                                                    second ? "EX,EY,EZ,TX,TY,TZ" : "X,Y,Z", key));
        if (!first.times.empty() && v[0] <= first.times.back())
            throw std::invalid_argument("key times must increase");
        first.times.push_back(v[0]);
        first.values.push_back({v[1], v[2], v[3]});
        if (second) second->times.push_back(v[0]), second->values.push_back({v[4], v[5], v[6]});
    }
    if (first.times.empty()) throw std::invalid_argument("no keys");
}

// The camera must see along a defined direction at every time of its path, as a single camera must: eye apart from target and the view not along `up` (lookAt degenerates: a black image).
// Between keys eye - target moves linearly, d(u) = mix(d0, d1, u), and so does c(u) = d(u) x up; both
// are checked at the keys and where each comes closest to zero.
void checkCameraPath(const Keyframes& eye, const Keyframes& target, const glm::vec3& cameraUp) {
    const glm::vec3 up = glm::length(cameraUp) > 0.0f ? glm::normalize(cameraUp) : glm::vec3(0.0f, 1.0f, 0.0f);
    const auto degenerate = [&](const glm::vec3& d) {
        const float length = glm::length(d);
        return !(length >= 1e-6f) || glm::length(glm::cross(d / length, up)) < 1e-3f;
    };
    const auto closestToZero = [](const glm::vec3& a, const glm::vec3& b) {
        const glm::vec3 ab = b - a;
        const float len2 = glm::dot(ab, ab);
        return len2 > 0.0f ? std::clamp(-glm::dot(a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    };
    for (size_t k = 0; k < eye.times.size(); ++k) {
        const glm::vec3 d0 = target.values[k] - eye.values[k];
        const glm::vec3 d1 = k + 1 < eye.times.size() ? target.values[k + 1] - eye.values[k + 1] : d0;
        for (float u : {0.0f, closestToZero(d0, d1), closestToZero(glm::cross(d0, up), glm::cross(d1, up))}) {
            if (!degenerate(glm::mix(d0, d1, u))) continue;
            const double t = eye.times[k] + double(u) * (k + 1 < eye.times.size() ? eye.times[k + 1] - eye.times[k] : 0.0);
            throw MotionError(MotionError::Input::CameraKeys, 0, fmt::format(
                "at t = {:.4g} s the {}", t,
                glm::length(glm::mix(d0, d1, u)) < 1e-6f ? "eye and target coincide"
                                                          : "view direction (target - eye) is parallel to the up vector"));
        }
    }
}

glm::vec3 rotateY(const glm::vec3& v, float angle) {
    const float c = std::cos(angle), s = std::sin(angle);
    return {c * v.x + s * v.z, v.y, -s * v.x + c * v.z};
}

}  // namespace

glm::vec3 Keyframes::at(double t) const {
    if (times.empty()) return glm::vec3(0.0f);
    if (t <= times.front()) return values.front();
    if (t >= times.back()) return values.back();
    const size_t k = size_t(std::upper_bound(times.begin(), times.end(), float(t)) - times.begin()) - 1;
    const float u = float((t - times[k]) / (times[k + 1] - times[k]));
    return glm::mix(values[k], values[k + 1], u);
}

glm::vec3 sunDirection(float azimuthDeg, float elevationDeg) {
    const float az = glm::radians(azimuthDeg), el = glm::radians(elevationDeg);
    return -glm::vec3(std::cos(el) * std::cos(az), std::sin(el), std::cos(el) * std::sin(az));
}

SunPath parseSunPath(const std::string& text) {
    const std::vector<float> v = numbers(text);
    if (v.size() != 5 || v[4] <= 0.0f) throw std::invalid_argument("expected AZ0,EL0,AZ1,EL1,SECONDS (degrees; SECONDS > 0)");
    return {{v[0], v[1]}, {v[2], v[3]}, v[4]};
}

LightPath parseLightPath(const std::string& text) {
    const size_t colon = text.find(':');
    if (colon == std::string::npos) throw std::invalid_argument("expected N:T,X,Y,Z;T,X,Y,Z;...");
    const std::vector<float> n = numbers(text.substr(0, colon));
    if (n.size() != 1 || n[0] < 0.0f || n[0] != std::floor(n[0]))
        throw std::invalid_argument("N must be a light index");
    LightPath path{size_t(n[0]), {}};
    parseKeys(text.substr(colon + 1), path.positions, nullptr);
    return path;
}

CameraKeys parseCameraKeys(const std::string& text) {
    CameraKeys keys;
    parseKeys(text, keys.eye, &keys.target);
    return keys;
}

ParsedMotionPaths::ParsedMotionPaths(const MotionPaths& paths) : builtinDefault(paths.builtinDefault) {
    if (!paths.sun.empty()) sun = parseSunPath(paths.sun);
    for (const std::string& l : paths.lights) lights.push_back(parseLightPath(l));
    if (!paths.camera.empty()) camera = parseCameraKeys(paths.camera);
}

SceneMotion::SceneMotion(const Scene& scene, const Camera& camera, const std::vector<Light>& lights,
                         const ParsedMotionPaths& paths, const AnimationOptions& animation)
    : scene_(scene), camera0_(camera), lights0_(lights), animation_(animation), animated_(isAnimated(scene)) {
    if (animation.animation >= 0 && size_t(animation.animation) >= scene.animations.size())
        throw MotionError(MotionError::Input::Animation, 0,
                          fmt::format("the scene has {} animation(s)", scene.animations.size()));
    if (paths.sun) sun_.push_back(*paths.sun);
    for (size_t i = 0; i < paths.lights.size(); ++i) {
        const LightPath& path = paths.lights[i];
        if (path.light >= lights.size())
            throw MotionError(MotionError::Input::LightPath, i, fmt::format("the frame has {} light(s)", lights.size()));
        if (lights[path.light].type == LightType::Directional)
            throw MotionError(MotionError::Input::LightPath, i,
                              "a directional light has no position (a sun path turns it)");
        lightPaths_.push_back(path);
    }
    if (paths.camera) camera_ = paths.camera->eye, cameraTarget_ = paths.camera->target;
    if (paths.camera) checkCameraPath(camera_, cameraTarget_, camera.up);
    const bool anyPath = !sun_.empty() || !lightPaths_.empty() || !camera_.times.empty();
    // Built-in scenes move their own light by default (never lights given with --light).
    if (paths.builtinDefault && !anyPath && !animated_ && !lights.empty() && lights[0].name == scene.lights[0].name &&
        lights[0].position == scene.lights[0].position) {
        if (scene.name == "cornell")  // the spot sweeps across the box, 0.5 m either way in 6 s
            periodic_.push_back({0, 6.0f, {0.5f, 0.0f, 0.0f}, false, {}});
        else if (scene.name == "hair")  // the key light orbits the head once in 8 s
            periodic_.push_back({0, 8.0f, {}, true, scene.bounds.center()});
    }
}

bool SceneMotion::moves() const {
    return animated_ || !sun_.empty() || !lightPaths_.empty() || !camera_.times.empty() || !periodic_.empty();
}

ScenePose SceneMotion::at(double t) const {
    ScenePose pose{camera0_, lights0_, {}};
    const std::vector<glm::mat4> nodes = nodeWorldTransforms(scene_, animated_ ? t : 0.0, animation_);
    pose.instances = instanceTransforms(scene_, nodes);
    if (animated_) {
        placeOnNodes(scene_, nodes, pose.lights);
        placeOnNodes(scene_, nodes, pose.camera);
    }
    for (const SunPath& sun : sun_) {
        const float u = float(std::clamp(t / sun.seconds, 0.0, 1.0));
        const glm::vec2 ae = glm::mix(sun.from, sun.to, u);
        for (Light& l : pose.lights)
            if (l.type == LightType::Directional) l.direction = sunDirection(ae.x, ae.y);
    }
    for (const auto& [index, keys] : lightPaths_) pose.lights[index].position = keys.at(t);
    for (const Periodic& p : periodic_) {
        Light& l = pose.lights[p.light];
        const float phase = float(2.0 * glm::pi<double>() * t / p.period);
        if (p.orbit) {
            l.position = p.center + rotateY(l.position - p.center, phase);
            l.direction = rotateY(l.direction, phase);
        } else {
            l.position += p.sweep * std::sin(phase);
        }
    }
    if (!camera_.times.empty()) {
        pose.camera.eye = camera_.at(t);
        pose.camera.target = cameraTarget_.at(t);
    }
    return pose;
}

}  // namespace penumbra
