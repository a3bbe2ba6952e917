// Motion over time: glTF animation (src/scene/animation.h) plus motion paths for scenes without
// animations (the sun's azimuth/elevation, spot and point light positions, camera keyframes), and
// the built-in scenes' default motions. Evaluates everything that moves at a time t (seconds).
#pragma once
#include <string>
#include <vector>

#include "scene/animation.h"

namespace penumbra {

// Paths as given on the command line (README "Motion"); empty = none.
struct MotionPaths {
    std::string sun;                 // --sun-path AZ0,EL0,AZ1,EL1,SECONDS (degrees)
    std::vector<std::string> lights; // --light-path N:T,X,Y,Z;T,X,Y,Z;...
    std::string camera;              // --camera-keys T,EX,EY,EZ,TX,TY,TZ;...
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
    // `camera` and `lights` are the frame's (after --camera / --light); throws std::invalid_argument
    // for a malformed path (one line).
    SceneMotion(const Scene& scene, const Camera& camera, const std::vector<Light>& lights, const MotionPaths& paths,
                const AnimationOptions& animation);
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
    std::vector<std::pair<size_t, Keyframes>> lightPaths_;  // light index, positions
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

// Checks the syntax of the paths without a scene (the CLI's early check).
void checkMotionPaths(const MotionPaths& paths);

}  // namespace penumbra
