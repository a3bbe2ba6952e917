// What the viewer shows, without the window: the render options as given (flag and values, applied by
// their option rows: `set` lines, the UI and `penumbra render` share one parser and one set of
// rules), the loaded scene, the live camera and lights, and the renderer they drive. Usable headless
// (tests).
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "frame/frame_args.h"
#include "renderer/renderer.h"
#include "scene/motion.h"

namespace penumbra::view {

// The options of `render` as the UI lists them: CLI name, current value, help with the range.
struct OptionInfo {
    std::string name;     // without dashes: "shadow-res"
    std::string value;    // current value as the CLI would take it ("" for an unset flag)
    std::string help;     // description and accepted values
    bool flag = false;    // takes on|off
    std::vector<std::string> choices;  // named values (e.g. hard, pcf, ...), empty for free values
    std::string group;    // the panel: its option table's title
};

class ViewSession {
public:
    ViewSession(vk::Context& ctx, std::vector<FrameArg> args);
    // `parsed`: what parseFrameArgs(args) gives, parsed already (the command line's `view`).
    ViewSession(vk::Context& ctx, std::vector<FrameArg> args, ParsedFrame parsed);

    // `set OPTION VALUE`: as if `--OPTION VALUE` replaced that option's earlier value on the command
    // line; flags take on|off. Every cross-option rule is checked; on error (std::invalid_argument
    // with the CLI's message) nothing changes.
    void set(const std::string& option, const std::string& value);
    // The drawable size (window resized): the width and height options.
    void resize(uint32_t width, uint32_t height);

    // The live view: the camera and lights start as the options give them and then move freely.
    const Camera& camera() const { return camera_; }
    void setCamera(const Camera& camera) { camera_ = camera; }
    const std::vector<Light>& lights() const { return lights_; }
    void setLights(std::vector<Light> lights);
    void setLight(size_t index, const Light& light);  // index == count appends; throws out of range
    // Scene time (seconds): animation and motion paths (docs/cli.md) at this time; `time T`,
    // play/pause. Starts at --time.
    float time = 0.0f;
    bool playing = false;
    // Anything moves (animation, a motion path, the built-in scene's default motion).
    bool moves() const { return motion_ && motion_->moves(); }
    // What the next frame shows: the live camera and lights, moved by the motion at `time` (the
    // camera only when camera keys are given, so that it can be flown otherwise).
    FrameInputs frameInputs() const;
    // Pixel probe: every AOV at this pixel of the rendered image, read back with its frame
    // (Renderer::probe()); the cursor sets it unless a script pinned it (`probe X Y`).
    std::optional<glm::uvec2> probePixel;
    bool probePinned = false;
    // The panels over the image (F1, `panels on|off`).
    bool showPanels = true;

    const Scene& scene() const { return gpuScene_->scene(); }
    const RenderSettings& settings() const { return frame_.settings; }
    const FrameOptions& frameOptions() const { return frame_.options; }
    std::vector<OptionInfo> options() const;
    // Replaces the scene (drag and drop): on a load error the old one stays and the error is thrown.
    void loadScene(const std::string& path);

    // The renderer over the scene, with the current settings applied (Renderer::apply: per-frame
    // values cost nothing, structure and sizes rebuild only what they own).
    Renderer& renderer();
    // Whether the renderer's newest completed frame (its pass timings and pixel probe) was rendered
    // with the current settings, so that the panels may show it as the state of the image.
    bool frameMatchesSettings() const;
    // After a settings change, waits for the first frame submitted with them (once), so that the
    // panels drawn next show that frame rather than one of the old settings.
    void catchUpPanels();
    // One frame of the live camera and lights, with the viewer's commands after its last pass.
    // With a split view, the B renderer's frame is submitted first (same queue: A's commands see it).
    void submit(const FrameHooks& hooks);

    // A/B split view: a second Renderer over the same GpuScene with one option changed; null when off.
    void setSplit(const std::string& option, const std::string& value);  // throws like set()
    void clearSplit();
    Renderer* rendererB() { return splitOption_.empty() ? nullptr : rendererB_.get(); }
    const std::string& splitLabel() const { return splitLabel_; }
    // One frame, waited for (headless use and screenshots).
    void renderAndWait();
    // Writes the last finished frame's tone-mapped image (.png) or linear values (.exr).
    void writeImage(const std::string& path);

private:
    void adopt(std::vector<FrameArg> args, ParsedFrame parsed);
    static std::vector<FrameArg> withArg(std::vector<FrameArg> args, const std::string& option,
                                         const std::string& value);
    void updateSplit();
    void rebuildMotion();

    vk::Context& ctx_;
    std::vector<FrameArg> args_;
    ParsedFrame frame_;
    std::unique_ptr<GpuScene> gpuScene_;  // the scene as loaded (its own lights and cameras), uploaded once
    Camera camera_;
    std::vector<Light> lights_;
    std::unique_ptr<SceneMotion> motion_;  // over the live camera and lights (rebuilt when they change)
    std::unique_ptr<Renderer> renderer_;
    std::string splitOption_, splitValue_, splitLabel_;
    RenderSettings settingsB_;
    std::unique_ptr<Renderer> rendererB_;
    bool settingsChanged_ = false;
    uint64_t settingsFrame_ = 0;  // the renderer's first frame with the current settings
    std::optional<uint64_t> newestCompleted_;  // the renderer's newest frame whose timings were collected
};

}  // namespace penumbra::view
