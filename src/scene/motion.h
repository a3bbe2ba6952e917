// Motion over time: glTF animation (src/scene/animation.h) plus motion paths for scenes without
// animations (the sun's azimuth/elevation, spot and point light positions, camera keyframes), and
// the built-in scenes' default motions. Evaluates everything that moves at a time t (seconds).
#pragma once
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/animation.h"

namespace penumbra {

// Paths as text (docs/cli.md: --sun-path, --light-path, --camera-keys); empty = none.
struct MotionPaths {
    std::string sun;                 // AZ0,EL0,AZ1,EL1,SECONDS (degrees)
    std::vector<std::string> lights; // N:T,X,Y,Z;T,X,Y,Z;...
    std::string camera;              // T,EX,EY,EZ,TX,TY,TZ;...
    bool builtinDefault = true;      // the built-in scene's default motion when no path is given (--no-motion: off)
};

// Linear keyframes of a vec3 (held before the first and after the last key).
struct Keyframes {
    std::vector<float> times;
    std::vector<glm::vec3> values;
    glm::vec3 at(double t) const;
};

struct SunPath {
    glm::vec2 from{0.0f}, to{0.0f};  // azimuth, elevation (degrees)
    float seconds = 1.0f;
};

struct LightPath {
    size_t light = 0;     // index among the frame's lights
    Keyframes positions;
};

struct CameraKeys {
    Keyframes eye, target;  // same times
};

// The paths parsed: each throws std::invalid_argument with the reason (naming no option; the
// caller knows which input it parsed).
SunPath parseSunPath(const std::string& text);      // AZ0,EL0,AZ1,EL1,SECONDS
LightPath parseLightPath(const std::string& text);  // N:T,X,Y,Z;T,X,Y,Z;...
CameraKeys parseCameraKeys(const std::string& text);  // T,EX,EY,EZ,TX,TY,TZ;...

struct ParsedMotionPaths {
    ParsedMotionPaths() = default;
    // Parses each path of `paths` (std::invalid_argument for a malformed one): text converts.
    ParsedMotionPaths(const MotionPaths& paths);  // NOLINT(google-explicit-constructor)
    std::optional<SunPath> sun;
    std::vector<LightPath> lights;
    std::optional<CameraKeys> camera;
    bool builtinDefault = true;
};

// A motion that does not fit the scene it moves; `input` and `index` (the light path's entry) say
// which input, for the caller to name.
struct MotionError : std::invalid_argument {
    enum class Input { Animation, LightPath, CameraKeys };
    MotionError(Input in, size_t i, const std::string& why) : std::invalid_argument(why), input(in), index(i) {}
    Input input;
    size_t index;
};

// Direction a sun at azimuth/elevation (degrees) travels: azimuth from +X towards +Z, elevation above
// the horizon.
glm::vec3 sunDirection(float azimuthDeg, float elevationDeg);

// What one frame shows at a time.
struct ScenePose {
    Camera camera;
    std::vector<Light> lights;
    std::vector<glm::mat4> instances;  // per Scene::instances
};

class SceneMotion {
public:
    // `camera` and `lights` are the frame's (after the camera and light overrides); throws MotionError
    // for a path or animation that does not fit them (one line).
    SceneMotion(const Scene& scene, const Camera& camera, const std::vector<Light>& lights,
                const ParsedMotionPaths& paths, const AnimationOptions& animation);
    ScenePose at(double t) const;
    // True when anything moves (animation, a path or a default motion).
    bool moves() const;
    bool cameraMoves() const { return !camera_.times.empty(); }
    bool animated() const { return animated_; }

private:
    const Scene& scene_;
    Camera camera0_;
    std::vector<Light> lights0_;
    AnimationOptions animation_;
    bool animated_ = false;
    std::vector<SunPath> sun_;                          // 0 or 1
    std::vector<LightPath> lightPaths_;
    struct Periodic {
        size_t light;
        float period;        // seconds
        glm::vec3 sweep;     // sweep: position += sweep * sin(2 pi t / period)
        bool orbit;          // orbit: position and direction turn about the vertical axis through `center`
        glm::vec3 center;
    };
    std::vector<Periodic> periodic_;                    // the built-in scenes' default motions
    Keyframes camera_;                                  // eye keys
    Keyframes cameraTarget_;                            // target keys (same times)
};

}  // namespace penumbra
