#include "view/camera_control.h"

#include <algorithm>
#include <cmath>

#include <GLFW/glfw3.h>
#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::view {
namespace {

constexpr float kLookRadiansPerPixel = 0.004f;

}  // namespace

void CameraControl::reset(const Camera&, const Bounds& bounds) {
    sceneRadius_ = bounds.empty() ? 1.0f : std::max(bounds.radius(), 1e-3f);
    speed = 0.5f * sceneRadius_;  // crosses the scene in about four seconds
}

bool CameraControl::update(GLFWwindow* window, double dt, double scroll, bool mouse, bool keys, Camera& camera) {
    double x, y;
    glfwGetCursorPos(window, &x, &y);
    const int button = mode == Mode::Fly ? GLFW_MOUSE_BUTTON_RIGHT : GLFW_MOUSE_BUTTON_LEFT;
    const bool down = glfwGetMouseButton(window, button) == GLFW_PRESS;
    if (down && !dragging_ && mouse) dragging_ = true;  // a drag starts outside the UI, then owns the mouse
    if (!down) dragging_ = false;
    dragX_ = dragging_ ? float(x - lastX_) : 0.0f;
    dragY_ = dragging_ ? float(y - lastY_) : 0.0f;
    lastX_ = x;
    lastY_ = y;
    if (!mouse) scroll = 0.0;
    return mode == Mode::Fly ? fly(window, dt, scroll, keys, camera) : orbit(scroll, camera);
}

// Turns the view direction by the drag (yaw about the up axis, pitch kept off the poles); around
// the target (orbit) the eye moves, otherwise the target does.
bool CameraControl::look(float dx, float dy, Camera& camera, bool aroundTarget) {
    if (dx == 0.0f && dy == 0.0f) return false;
    const glm::vec3 up = glm::normalize(camera.up);
    glm::vec3 forward = camera.target - camera.eye;
    const float distance = glm::length(forward);
    forward /= distance;
    const float sign = aroundTarget ? 1.0f : -1.0f;
    glm::mat4 turn = glm::rotate(glm::mat4(1.0f), sign * dx * kLookRadiansPerPixel, up);
    const glm::vec3 right = glm::normalize(glm::cross(forward, up));
    const float pitch = std::asin(std::clamp(glm::dot(forward, up), -1.0f, 1.0f));
    const float newPitch = std::clamp(pitch + sign * dy * kLookRadiansPerPixel, -1.5f, 1.5f);
    turn = glm::rotate(turn, newPitch - pitch, right);
    const glm::vec3 dir = glm::normalize(glm::vec3(turn * glm::vec4(forward, 0.0f)));
    if (aroundTarget) camera.eye = camera.target - dir * distance;
    else camera.target = camera.eye + dir * distance;
    return true;
}

bool CameraControl::fly(GLFWwindow* window, double dt, double scroll, bool keys, Camera& camera) {
    if (scroll != 0.0) speed = std::clamp(speed * std::pow(1.25f, float(scroll)), 1e-4f * sceneRadius_,
                                          100.0f * sceneRadius_);
    bool moved = look(dragX_, dragY_, camera, false);
    if (!keys) return moved;
    const glm::vec3 up = glm::normalize(camera.up);
    const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, up));
    auto held = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS ? 1.0f : 0.0f; };
    const glm::vec3 step = forward * (held(GLFW_KEY_W) - held(GLFW_KEY_S)) +
                           right * (held(GLFW_KEY_D) - held(GLFW_KEY_A)) + up * (held(GLFW_KEY_E) - held(GLFW_KEY_Q));
    if (step == glm::vec3(0.0f)) return moved;
    const glm::vec3 delta = step * speed * float(dt);
    camera.eye += delta;
    camera.target += delta;
    return true;
}

bool CameraControl::orbit(double scroll, Camera& camera) {
    bool moved = look(dragX_, dragY_, camera, true);
    if (scroll != 0.0) {
        const glm::vec3 offset = camera.eye - camera.target;
        camera.eye = camera.target + offset * std::pow(0.85f, float(scroll));
        moved = true;
    }
    return moved;
}

}  // namespace penumbra::view
