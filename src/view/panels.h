// The viewer's UI: scene and camera, lights, every render option grouped per technique (edited
// through the same CLI definitions as `render`), the debug view (AOV), GPU timings and frame times.
#pragma once
#include <deque>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "view/camera_control.h"
#include "view/overlays.h"
#include "view/session.h"
#include "vk/swapchain.h"

namespace penumbra::view {

// What the panels showed in the last frame drawn: their windows' rectangles, the pass table and
// every option's value (`panels-state` writes it for tests and for checking a capture).
struct PanelsState {
    struct Rect {
        std::string window;
        float x = 0, y = 0, width = 0, height = 0;
    };
    float displayWidth = 0, displayHeight = 0;
    std::vector<Rect> windows;
    std::vector<std::string> passes;  // the pass table's rows ("" while it waits for the frame)
    std::vector<std::pair<std::string, std::string>> options;  // name, value as shown
    std::vector<std::pair<std::string, glm::vec3>> probe;        // the pixel probe's rows as shown
    // The part of the window the panels cover (their rectangles clipped to it; overlaps count twice).
    float coverage() const;
    std::string text() const;
};

class Panels {
public:
    void draw(ViewSession& session, CameraControl& control, const vk::Swapchain& swapchain);
    // Per-frame animation the UI turned on (the turning sun).
    void animate(ViewSession& session, double dt);
    void recordFrameTime(double ms);
    // Turns the first directional light by a drag of (dx, dy) pixels (ctrl + left-drag).
    void dragSun(ViewSession& session, float dx, float dy);
    const OverlayOptions& overlays() const { return overlays_; }
    const PanelsState& state() const { return state_; }
    // Drag and drop: a bad file shows its error, the old scene stays.
    void loadScene(ViewSession& session, const std::string& path);

private:
    void sceneWindow(ViewSession& session, CameraControl& control);
    void timeSection(ViewSession& session);
    void lightsSection(ViewSession& session);
    void optionsSection(ViewSession& session);
    void debugViewSliders(ViewSession& session);
    void splitSection(ViewSession& session);
    void splitLabels(ViewSession& session);
    void timingsWindow(ViewSession& session, const vk::Swapchain& swapchain);
    void probeWindow(ViewSession& session);
    void apply(ViewSession& session, const std::string& option, const std::string& value);
    void placeWindow(const char* name, float x, float y, float width, float height);
    void recordWindow(const char* name);

    std::deque<float> frameMs_;
    bool passScopes_ = true;  // the timings window's per-pass table
    std::map<std::string, std::string> edits_;  // option text fields being typed in
    std::string error_;
    std::string splitEdit_ = "shadow pcss";  // the B side's option and value
    OverlayOptions overlays_;
    bool turnSun_ = false;
    float sunDegreesPerSecond_ = 10.0f;
    PanelsState state_;
    bool relayout_ = true;  // the display size changed: the windows take their share of it again
};

}  // namespace penumbra::view
