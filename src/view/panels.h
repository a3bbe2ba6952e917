// The viewer's UI: scene and camera, lights, every render option grouped per technique (edited
// through the same CLI definitions as `render`), the debug view (AOV), GPU timings and frame times.
#pragma once
#include <deque>
#include <map>
#include <string>

#include "view/camera_control.h"
#include "view/overlays.h"
#include "view/session.h"
#include "vk/swapchain.h"

namespace penumbra::view {

class Panels {
public:
    void draw(ViewSession& session, CameraControl& control, const vk::Swapchain& swapchain);
    // Per-frame animation the UI turned on (the turning sun).
    void animate(ViewSession& session, double dt);
    void recordFrameTime(double ms);
    // Turns the first directional light by a drag of (dx, dy) pixels (ctrl + left-drag).
    void dragSun(ViewSession& session, float dx, float dy);
    const OverlayOptions& overlays() const { return overlays_; }
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

    std::deque<float> frameMs_;
    bool passScopes_ = true;  // the timings window's per-pass table
    std::map<std::string, std::string> edits_;  // option text fields being typed in
    std::string error_;
    std::string splitEdit_ = "shadow pcss";  // the B side's option and value
    OverlayOptions overlays_;
    bool turnSun_ = false;
    float sunDegreesPerSecond_ = 10.0f;
};

}  // namespace penumbra::view
