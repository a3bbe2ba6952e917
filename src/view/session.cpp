#include "view/session.h"

#include <algorithm>

#include <fmt/format.h>

#include "core/sky.h"
#include "frame/frame_args.h"
#include "frame/light_filters.h"
#include "frame/option_text.h"
#include "io/image_io.h"
#include "renderer/device_budget.h"

namespace penumbra::view {
namespace {

// The panel of the scene argument: the group a command line parser gives an option without one.
constexpr const char* kSceneGroup = "Options";

bool sameCamera(const FrameOptions& a, const FrameOptions& b) {
    return a.camera == b.camera && a.cameraIndex == b.cameraIndex && a.view == b.view;
}

}  // namespace

ViewSession::ViewSession(vk::Context& ctx, std::vector<FrameArg> args) : ctx_(ctx) {
    ParsedFrame parsed = parseFrameArgs(args);
    adopt(std::move(args), std::move(parsed));
}

ViewSession::ViewSession(vk::Context& ctx, std::vector<FrameArg> args, ParsedFrame parsed) : ctx_(ctx) {
    adopt(std::move(args), std::move(parsed));
}

// Takes a parsed argument list: reloads the scene, re-derives the lights and the camera only where
// their options changed (moved lights and a flown camera survive other changes).
void ViewSession::adopt(std::vector<FrameArg> args, ParsedFrame p) {
    const bool newScene = !gpuScene_ || p.options.scene != frame_.options.scene ||
                          p.options.builtin.hairStrands != frame_.options.builtin.hairStrands;
    std::unique_ptr<GpuScene> uploaded;
    if (newScene) uploaded = std::make_unique<GpuScene>(ctx_, penumbra::loadScene(p.options.scene, p.options.builtin));
    const Scene& s = newScene ? uploaded->scene() : gpuScene_->scene();
    std::vector<Light> lights = lights_;
    if (newScene || p.options.lights != frame_.options.lights || p.options.view != frame_.options.view) {
        lights = frameLights(p.options, s);
    } else if (p.options.lightFilters != frame_.options.lightFilters) {
        for (Light& l : lights) l.shadowFilter = ShadowFilter::Default;
        applyLightFilters(p.options.lightFilters, lights);
    }
    const bool newCamera = newScene || !sameCamera(p.options, frame_.options);
    const Camera camera = newCamera ? frameCamera(p.options, s) : camera_;
    checkDeviceBudget(ctx_, p.settings, s, lights);  // as `render` checks it before any work
    resolveAutoSky(p.settings.lighting.sky, lights);
    // Nothing above threw: commit.
    if (newScene) {
        renderer_.reset();  // they draw the old scene
        rendererB_.reset();
        newestCompleted_.reset();
        gpuScene_ = std::move(uploaded);
    }
    if (newScene || p.options.time != frame_.options.time) time = float(p.options.time);
    args_ = std::move(args);
    frame_.options = std::move(p.options);
    frame_.settings = p.settings;
    lights_ = std::move(lights);
    camera_ = camera;
    settingsChanged_ = true;
    rebuildMotion();
}

void ViewSession::rebuildMotion() {
    try {
        motion_ = std::make_unique<SceneMotion>(scene(), camera_, lights_, frame_.options.parsedMotion,
                                                frame_.options.animation);
    } catch (const std::invalid_argument&) {
        motion_.reset();  // a light path names a light that was removed: the lights stay where they are
    }
}

FrameInputs ViewSession::frameInputs() const {
    FrameInputs in{camera_, lights_, {}, probePixel};
    if (!moves()) return in;
    ScenePose pose = motion_->at(time);
    in.lights = std::move(pose.lights);
    in.instances = std::move(pose.instances);
    if (motion_->cameraMoves()) in.camera = pose.camera;
    return in;
}

void ViewSession::set(const std::string& option, const std::string& value) {
    const std::vector<OptionInfo> known = options();
    const auto it = std::find_if(known.begin(), known.end(), [&](const OptionInfo& o) { return o.name == option; });
    if (it == known.end()) throw std::invalid_argument(fmt::format("unknown option '{}'", option));
    if (it->flag && value != "on" && value != "off")
        throw std::invalid_argument(fmt::format("{}: a flag takes on or off, not '{}'", option, value));
    std::vector<FrameArg> args = withArg(args_, option, value);
    ParsedFrame parsed = parseFrameArgs(args);
    adopt(std::move(args), std::move(parsed));
    updateSplit();
}

std::vector<FrameArg> ViewSession::withArg(std::vector<FrameArg> args, const std::string& option,
                                           const std::string& value) {
    const std::string name = option == "scene" ? option : "--" + option;
    std::erase_if(args, [&](const FrameArg& a) { return a.name == name; });
    args.push_back({name, {value}});
    return args;
}

void ViewSession::setSplit(const std::string& option, const std::string& value) {
    if (option == "scene" || option == "width" || option == "height" || option == "strands")
        throw std::invalid_argument("the split view shares the scene and the image size: pick another option");
    settingsB_ = parseFrameArgs(withArg(args_, option, value)).settings;
    splitOption_ = option;
    splitValue_ = value;
    splitLabel_ = fmt::format("B: --{} {}", option, value);
    if (rendererB_) rendererB_->apply(settingsB_);
    else rendererB_ = std::make_unique<Renderer>(ctx_, *gpuScene_, settingsB_);
}

void ViewSession::clearSplit() {
    splitOption_.clear();
    rendererB_.reset();
}

// A's options changed: B follows them, keeping its own option (or ends when that no longer parses).
void ViewSession::updateSplit() {
    if (splitOption_.empty()) return;
    if (!rendererB_) return setSplit(splitOption_, splitValue_);  // a new scene dropped it
    try {
        settingsB_ = parseFrameArgs(withArg(args_, splitOption_, splitValue_)).settings;
        rendererB_->apply(settingsB_);
    } catch (const std::invalid_argument&) {
        clearSplit();
    }
}

void ViewSession::resize(uint32_t width, uint32_t height) {
    if (width == frame_.settings.width && height == frame_.settings.height) return;
    set("width", std::to_string(width));
    set("height", std::to_string(height));
}

void ViewSession::setLights(std::vector<Light> lights) {
    lights_ = std::move(lights);
    rebuildMotion();
}

void ViewSession::setLight(size_t index, const Light& light) {
    if (index > lights_.size())
        throw std::invalid_argument(fmt::format("light {}: the scene has {} light(s)", index, lights_.size()));
    if (index == lights_.size()) lights_.push_back(light);
    else lights_[index] = light;
    rebuildMotion();
}

void ViewSession::loadScene(const std::string& path) { set("scene", path); }

std::vector<OptionInfo> ViewSession::options() const {
    const std::vector<const OptionTable*> tables = frameOptionTables();
    std::vector<OptionInfo> out;
    for (const FrameOptionRef& ref : frameOptionRefs(frame_)) {
        OptionInfo info;
        info.name = ref.name.rfind("--", 0) == 0 ? ref.name.substr(2) : ref.name;
        if (const OptionRow* row = ref.row) {
            // The state of the frame on screen, not the last value typed.
            info.help = optionHelp(*row, tables) + " [" + row->rangeText() + "]";
            info.group = row->group;
            info.flag = row->kind == OptionKind::Bool || row->bareFlag;
            if (row->kind == OptionKind::Choice) info.choices = row->choices;
            info.value = row->value(ref.settings);
        } else {  // the scene, as it was given
            info.help = sceneArgumentHelp();
            info.group = kSceneGroup;
            for (const FrameArg& a : args_)
                if (a.name == ref.name && !a.values.empty()) info.value = a.values.back();
        }
        out.push_back(std::move(info));
    }
    return out;
}

Renderer& ViewSession::renderer() {
    if (!renderer_) renderer_ = std::make_unique<Renderer>(ctx_, *gpuScene_, frame_.settings);
    else if (settingsChanged_) renderer_->apply(frame_.settings);
    if (settingsChanged_) settingsFrame_ = renderer_->framesSubmitted();
    settingsChanged_ = false;
    return *renderer_;
}

bool ViewSession::frameMatchesSettings() const {
    return renderer_ && !settingsChanged_ && newestCompleted_ && *newestCompleted_ >= settingsFrame_;
}

void ViewSession::catchUpPanels() {
    Renderer& r = renderer();
    const auto takeCompleted = [&] {
        for (const FrameTimings& t : r.takeCompletedTimings()) newestCompleted_ = t.frame;
    };
    takeCompleted();
    if (frameMatchesSettings() || r.framesSubmitted() == settingsFrame_) return;
    r.finish();
    if (rendererB_) rendererB_->finish();
    takeCompleted();
}

void ViewSession::submit(const FrameHooks& hooks) {
    const FrameInputs in = frameInputs();
    if (Renderer* b = rendererB()) b->submit(in);
    renderer().submit(in, hooks);
}

void ViewSession::renderAndWait() {
    submit({});
    renderer_->finish();
    if (rendererB_) rendererB_->finish();
}

void ViewSession::writeImage(const std::string& path) {
    const std::string ext = fileExtension(path);
    if (!renderer_) throw std::logic_error("writeImage before the first frame");
    renderer_->finish();
    if (ext == ".png") writePng(path, frame_.settings.width, frame_.settings.height, renderer_->readLdr());
    else if (ext == ".exr") writeExr(path, frame_.settings.width, frame_.settings.height, renderer_->readHdr());
    else throw std::invalid_argument(fmt::format("{}: a screenshot must end in .png or .exr", path));
}

}  // namespace penumbra::view
