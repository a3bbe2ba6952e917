// Camera controls: fly (WASD move, Q/E down/up, right-drag look, wheel scales the speed) and orbit
// (left-drag turns around the target, wheel zooms). Speeds are scaled to the scene's size.
#pragma once
#include "scene/scene.h"

struct GLFWwindow;

namespace penumbra::view {

class CameraControl {
public:
    enum class Mode { Fly, Orbit };

    // A new scene or camera: the fly speed from the scene's size, the orbit pivot at the target.
    void reset(const Camera& camera, const Bounds& bounds);
    // Applies the input since the last call; true when the camera moved. `mouse`/`keys`: the UI
    // does not hold them.
    bool update(GLFWwindow* window, double dt, double scroll, bool mouse, bool keys, Camera& camera);

    Mode mode = Mode::Fly;
    float speed = 1.0f;  // fly speed, world units per second

private:
    bool fly(GLFWwindow* window, double dt, double scroll, bool keys, Camera& camera);
    bool orbit(double scroll, Camera& camera);
    bool look(float dx, float dy, Camera& camera, bool aroundTarget);

    float sceneRadius_ = 1.0f;
    double lastX_ = 0.0, lastY_ = 0.0;
    bool dragging_ = false;
    float dragX_ = 0.0f, dragY_ = 0.0f;  // cursor motion of the drag since the last call
};

}  // namespace penumbra::view
