#include "view/session.h"

#include <algorithm>

#include <fmt/format.h>

#include "app/cli_parse.h"
#include "core/sky.h"
#include "renderer/device_budget.h"
#include "app/shadow_cli.h"
#include "renderer/render_options.h"
#include "io/image_io.h"

namespace penumbra::view {
namespace {

std::string nameOf(const CLI::Option& opt) {
    return opt.get_lnames().empty() ? opt.get_name(true) : "--" + opt.get_lnames().front();  // the positional: "scene"
}

bool sameCamera(const FrameOptions& a, const FrameOptions& b) {
    return a.camera == b.camera && a.cameraIndex == b.cameraIndex && a.view == b.view;
}

}  // namespace

std::vector<CliArg> givenFrameArgs(const CLI::App& cmd) {
    CLI::App probe;
    FrameOptions o;
    RenderSettings rs;
    addFrameOptions(probe, o, rs);
    const std::vector<CLI::Option*> frameOptions = probe.get_options();  // one vector: begin and end of the same
    std::vector<CliArg> out;
    for (const CLI::Option* opt : cmd.get_options()) {
        if (opt->count() == 0) continue;
        const std::string name = nameOf(*opt);
        const bool isFrameOption = std::any_of(frameOptions.begin(), frameOptions.end(),
                                               [&](const CLI::Option* p) { return nameOf(*p) == name; });
        if (isFrameOption) out.push_back({name, opt->results()});
    }
    return out;
}

ViewSession::ViewSession(vk::Context& ctx, std::vector<CliArg> args) : ctx_(ctx) {
    Parsed parsed = parse(args);
    adopt(std::move(args), std::move(parsed));
}

// A fresh parse of the whole argument list by the render command's own option definitions: the
// same defaults, validators and cross-option rules as `penumbra render`.
ViewSession::Parsed ViewSession::parse(const std::vector<CliArg>& args) const {
    Parsed p;
    CLI::App app;
    addFrameOptions(app, p.options, p.settings);
    std::vector<std::string> argv;
    for (const CliArg& a : args)
        for (const std::string& v : a.values) argv.push_back(a.name == "scene" ? v : a.name + "=" + v);
    std::reverse(argv.begin(), argv.end());  // CLI11 takes its vector last argument first
    try {
        app.parse(argv);
    } catch (const CLI::ParseError& e) {
        throw std::invalid_argument(e.what());
    }
    checkFrameSettings(p.options, p.settings);
    return p;
}

// Takes a parsed argument list: reloads the scene, re-derives the lights and the camera only where
// their options changed (moved lights and a flown camera survive other changes).
void ViewSession::adopt(std::vector<CliArg> args, Parsed p) {
    const bool newScene = !gpuScene_ || p.options.scene != options_.scene ||
                          p.options.builtin.hairStrands != options_.builtin.hairStrands;
    std::unique_ptr<GpuScene> uploaded;
    if (newScene) uploaded = std::make_unique<GpuScene>(ctx_, penumbra::loadScene(p.options.scene, p.options.builtin));
    const Scene& s = newScene ? uploaded->scene() : gpuScene_->scene();
    std::vector<Light> lights = lights_;
    if (newScene || p.options.lights != options_.lights || p.options.view != options_.view) {
        lights = frameLights(p.options, s);
    } else if (p.options.lightFilters != options_.lightFilters) {
        for (Light& l : lights) l.shadowFilter = ShadowFilter::Default;
        applyLightFilters(p.options.lightFilters, lights);
    }
    const bool newCamera = newScene || !sameCamera(p.options, options_);
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
    if (newScene || p.options.time != options_.time) time = float(p.options.time);
    args_ = std::move(args);
    options_ = std::move(p.options);
    settings_ = p.settings;
    lights_ = std::move(lights);
    camera_ = camera;
    settingsChanged_ = true;
    rebuildMotion();
}

void ViewSession::rebuildMotion() {
    try {
        motion_ = std::make_unique<SceneMotion>(scene(), camera_, lights_, options_.motion, options_.animation);
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
    std::vector<CliArg> args = withArg(args_, option, value);
    Parsed parsed = parse(args);
    adopt(std::move(args), std::move(parsed));
    updateSplit();
}

std::vector<CliArg> ViewSession::withArg(std::vector<CliArg> args, const std::string& option,
                                         const std::string& value) {
    const std::string name = option == "scene" ? option : "--" + option;
    std::erase_if(args, [&](const CliArg& a) { return a.name == name; });
    args.push_back({name, {value}});
    return args;
}

void ViewSession::setSplit(const std::string& option, const std::string& value) {
    if (option == "scene" || option == "width" || option == "height" || option == "strands")
        throw std::invalid_argument("the split view shares the scene and the image size: pick another option");
    settingsB_ = parse(withArg(args_, option, value)).settings;
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
        settingsB_ = parse(withArg(args_, splitOption_, splitValue_)).settings;
        rendererB_->apply(settingsB_);
    } catch (const std::invalid_argument&) {
        clearSplit();
    }
}

void ViewSession::resize(uint32_t width, uint32_t height) {
    if (width == settings_.width && height == settings_.height) return;
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
    CLI::App app;
    FrameOptions o;
    RenderSettings rs;
    addFrameOptions(app, o, rs);
    // The row of a flag and the settings it reads, among the frame's tables and the inputs' tables.
    auto rowOf = [this](const std::string& flag) -> std::pair<const OptionRow*, const void*> {
        if (const FoundOption f = findRenderOption(flag); f.row) return {f.row, f.table->at(settings_)};
        for (const OptionTable* t : {&frameInputOptions(), &motionOptions()})
            if (const OptionRow* r = t->find(flag)) return {r, &options_};
        return {nullptr, nullptr};
    };
    std::vector<OptionInfo> out;
    for (const CLI::Option* opt : app.get_options()) {
        const std::string name = nameOf(*opt);
        if (name == "--help") continue;
        OptionInfo info;
        info.name = name.rfind("--", 0) == 0 ? name.substr(2) : name;
        info.help = opt->get_description();
        info.group = opt->get_group();
        const auto [row, settings] = rowOf(name);
        if (row) {
            // The state of the frame on screen, not the last value typed.
            info.flag = row->kind == OptionKind::Bool || row->bareFlag;
            info.help += " [" + row->rangeText() + "]";
            if (row->kind == OptionKind::Choice) info.choices = row->choices;
            info.value = row->value(settings);
        } else {
            for (const CliArg& a : args_)
                if (a.name == name && !a.values.empty()) info.value = a.values.back();
        }
        out.push_back(std::move(info));
    }
    return out;
}

Renderer& ViewSession::renderer() {
    if (!renderer_) renderer_ = std::make_unique<Renderer>(ctx_, *gpuScene_, settings_);
    else if (settingsChanged_) renderer_->apply(settings_);
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
    if (ext == ".png") writePng(path, settings_.width, settings_.height, renderer_->readLdr());
    else if (ext == ".exr") writeExr(path, settings_.width, settings_.height, renderer_->readHdr());
    else throw std::invalid_argument(fmt::format("{}: a screenshot must end in .png or .exr", path));
}

}  // namespace penumbra::view
