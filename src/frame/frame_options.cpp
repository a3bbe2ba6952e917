#include "frame/frame_options.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "core/texture_upload.h"
#include "frame/input_parse.h"
#include "frame/light_filters.h"
#include "frame/option_text.h"
#include "renderer/render_options.h"
#include "rsm/rsm_options.h"
#include "scene/named_views.h"

namespace penumbra {
namespace {

constexpr SettingsChange kInput = SettingsChange::PerFrame;  // frame inputs: the viewer re-derives them

// "a;b" lists and single compound values are checked by their parsers as they are given, and kept
// as text (the JSON and the viewer show them) beside the parsed value.
OptionTable makeInputTable() {
    using F = FrameOptions;
    OptionTableBuilder<F> t("inputs", "Scene, camera, lights, size");
    t.text("--camera", "camera", [](F& f) -> auto& { return f.camera; },
           [](const F& f) { return f.camera.empty() ? std::vector<std::string>{} : std::vector<std::string>{f.camera}; },
           [](F& f, const std::string& v) {
               f.parsedCamera = parseCamera(v);
               f.camera = v;
           },
           kInput, "Camera override: ex,ey,ez,tx,ty,tz,ux,uy,uz,fovy_deg (eye, target, up, vertical field of view)")
        .placeholder = "EYE,TARGET,UP,FOVY";
    t.alsoWrites([](F& f) -> auto& { return f.parsedCamera; });
    t.integer("--camera-index", "camera_index", [](F& f) -> auto& { return f.cameraIndex; }, 0, 1 << 20, kInput,
              "Which of the scene's (perspective) cameras to use");
    static const std::string viewHelp =
        "A named view of the scene: its camera, and its sun unless {inputs.lights} is given (" + namedViewList() + ")";
    t.text("--view", "view", [](F& f) -> auto& { return f.view; },
           [](const F& f) { return f.view.empty() ? std::vector<std::string>{} : std::vector<std::string>{f.view}; },
           [](F& f, const std::string& v) {
               const auto& views = namedViews();
               if (std::none_of(views.begin(), views.end(), [&](const NamedView& n) { return n.name == v; }))
                   throw std::invalid_argument("no scene has this view (" + namedViewList() + ")");
               f.view = v;
           },
           kInput, viewHelp.c_str())
        .placeholder = "NAME";
    OptionRow& light = t.text(
        "--light", "lights", [](F& f) -> auto& { return f.lights; }, [](const F& f) { return f.lights; },
        [](F& f, const std::string& v) {
            f.parsedLights.push_back(parseLight(v));
            f.lights.push_back(v);
        },
        kInput,
        "Replace the scene's lights (repeatable): directional,DX,DY,DZ,INTENSITY[,R,G,B] (direction of travel; "
        "irradiance), spot,PX,PY,PZ,DX,DY,DZ,INTENSITY,OUTER_DEG[,INNER_DEG] or point,PX,PY,PZ,INTENSITY "
        "(intensity in W/sr)");
    light.repeatable = true;
    light.placeholder = "TYPE,...";
    light.clear = [](void* f) { static_cast<F*>(f)->lights.clear(), static_cast<F*>(f)->parsedLights.clear(); };
    t.alsoWrites([](F& f) -> auto& { return f.parsedLights; });
    OptionRow& filters = t.text(
        "--light-shadow", "light_shadow", [](F& f) -> auto& { return f.lightFilters; },
        [](const F& f) { return f.lightFilters; },
        [](F& f, const std::string& v) {
            parseLightFilter(v);
            f.lightFilters.push_back(v);
        },
        kInput, "Filter of one light, overriding {frame.shadow_filter} (repeatable)");
    filters.repeatable = true;
    filters.placeholder = "N=FILTER";
    filters.clear = [](void* f) { static_cast<F*>(f)->lightFilters.clear(); };
    filters.group = "Shadow maps";
    t.integer("--strands", "strands", [](F& f) -> auto& { return f.builtin.hairStrands; }, 1, 2'000'000, kInput,
              "Hair strands of the built-in `hair` scene")
        .inGroup("Deep shadow maps and hair");
    return t.build();
}

OptionTable makeMotionTable() {
    using F = FrameOptions;
    OptionTableBuilder<F> t("motion", "Scene, camera, lights, size");
    t.real("--time", "time", [](F& f) -> auto& { return f.time; }, -1e6, 1e6, kInput,
           "Scene time in seconds (animation, motion paths)");
    t.integer("--animation", "animation", [](F& f) -> auto& { return f.animation.animation; }, 0, 1 << 20, kInput,
              "Play only glTF animation N")
        .orSpecial(-1, "every animation");
    t.boolean("--clamp", "clamp", [](F& f) -> auto& { return f.animation.clamp; }, kInput,
              "Hold the last key of animations instead of looping")
        .bareFlag = true;
    t.text("--sun-path", "sun_path", [](F& f) -> auto& { return f.motion.sun; },
           [](const F& f) { return f.motion.sun.empty() ? std::vector<std::string>{} : std::vector<std::string>{f.motion.sun}; },
           [](F& f, const std::string& v) {
               f.parsedMotion.sun = parseSunPath(v);
               f.motion.sun = v;
           },
           kInput,
           "Sun motion: AZ0,EL0,AZ1,EL1,SECONDS (degrees; every directional light)")
        .placeholder = "AZ0,EL0,AZ1,EL1,SECONDS";
    t.alsoWrites([](F& f) -> auto& { return f.parsedMotion.sun; });
    OptionRow& paths = t.text(
        "--light-path", "light_paths", [](F& f) -> auto& { return f.motion.lights; },
        [](const F& f) { return f.motion.lights; },
        [](F& f, const std::string& v) {
            f.parsedMotion.lights.push_back(parseLightPath(v));
            f.motion.lights.push_back(v);
        },
        kInput, "Light N's position keys (repeatable)");
    paths.repeatable = true;
    paths.placeholder = "N:T,X,Y,Z;T,X,Y,Z;...";
    paths.clear = [](void* f) { static_cast<F*>(f)->motion.lights.clear(), static_cast<F*>(f)->parsedMotion.lights.clear(); };
    t.alsoWrites([](F& f) -> auto& { return f.parsedMotion.lights; });
    t.text("--camera-keys", "camera_keys", [](F& f) -> auto& { return f.motion.camera; },
           [](const F& f) { return f.motion.camera.empty() ? std::vector<std::string>{} : std::vector<std::string>{f.motion.camera}; },
           [](F& f, const std::string& v) {
               f.parsedMotion.camera = parseCameraKeys(v);
               f.motion.camera = v;
           },
           kInput,
           "Camera motion keys, eye and target (seconds, metres)")
        .placeholder = "T,EX,EY,EZ,TX,TY,TZ;...";
    t.alsoWrites([](F& f) -> auto& { return f.parsedMotion.camera; });
    t.text("--no-motion", "no_motion", [](F& f) -> auto& { return f.motion.builtinDefault; },
           [](const F& f) { return std::vector<std::string>{f.motion.builtinDefault ? "off" : "on"}; },
           [](F& f, const std::string& v) {
               f.motion.builtinDefault = f.parsedMotion.builtinDefault = !(v == "on" || v == "true" || v == "1");
           },
           kInput, "No default motion of the built-in scenes")
        .bareFlag = true;
    t.alsoWrites([](F& f) -> auto& { return f.parsedMotion.builtinDefault; });
    return t.build();
}

}  // namespace

const OptionTable& frameInputOptions() {
    static const OptionTable table = makeInputTable();
    return table;
}

const OptionTable& motionOptions() {
    static const OptionTable table = makeMotionTable();
    return table;
}

std::string sceneArgumentHelp() {
    return "glTF file (.gltf/.glb) or built-in scene: " + fmt::format("{}", fmt::join(builtinSceneNames(), ", "));
}

void setFrameDefaults(RenderSettings& settings) {
    // The defaults show what penumbra is for: one bounce of indirect light (RSM, interpolated) and
    // soft shadows (PCF); docs/techniques/shadows.md and rsm.md give the reasons and the cost.
    settings.gi = GiMode::Rsm;
    settings.shadow.filter = ShadowFilter::Pcf;
}

SceneMotion checkedMotion(const FrameOptions& o, const PreparedFrame& f) {
    try {
        return SceneMotion(f.scene, f.camera, f.scene.lights, o.parsedMotion, o.animation);
    } catch (const MotionError& e) {
        const OptionTable& t = motionOptions();
        using In = MotionError::Input;
        const std::string& flag =
            e.input == In::Animation   ? t.flagOf<FrameOptions>([](FrameOptions& m) -> auto& { return m.animation.animation; })
            : e.input == In::LightPath ? t.flagOf<FrameOptions>([](FrameOptions& m) -> auto& { return m.motion.lights; })
                                       : t.flagOf<FrameOptions>([](FrameOptions& m) -> auto& { return m.motion.camera; });
        const std::string value = e.input == In::Animation   ? std::to_string(o.animation.animation)
                                  : e.input == In::LightPath ? o.motion.lights.at(e.index)
                                                             : o.motion.camera;
        refuseOption(*t.find(flag), value, e.what());
    }
}

void warnIfStill(const FrameOptions& o, const SceneMotion& motion, const Scene& scene) {
    if (o.time != 0.0 && !motion.moves())
        fmt::print(stderr, "penumbra: warning: {} {}: nothing in '{}' moves (no animation or motion path)\n",
                   motionOptions().flagOf<FrameOptions>([](FrameOptions& m) -> auto& { return m.time; }), o.time,
                   scene.name);
}

SceneMotion frameMotion(const FrameOptions& o, const PreparedFrame& f) {
    SceneMotion motion = checkedMotion(o, f);
    warnIfStill(o, motion, f.scene);
    return motion;
}

FrameInputs frameInputs(const SceneMotion& motion, double t) {
    ScenePose pose = motion.at(t);
    return {std::move(pose.camera), std::move(pose.lights), std::move(pose.instances)};
}

namespace {

const std::string& viewFlag() {
    return frameInputOptions().flagOf<FrameOptions>([](FrameOptions& f) -> auto& { return f.view; });
}

// The named view of --view, or null; throws naming the flag when the scene has no such view.
const NamedView* frameView(const FrameOptions& o) {
    if (o.view.empty()) return nullptr;
    try {
        return &findNamedView(o.scene, o.view);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(fmt::format("{} {}: {}", viewFlag(), o.view, e.what()));
    }
}

}  // namespace

void checkFrameSettings(const FrameOptions& o, RenderSettings& settings) {
    if (frameView(o) && o.parsedCamera)
        fmt::print(stderr, "penumbra: warning: {} replaces the camera of {} {}\n",
                   frameInputOptions().flagOf<FrameOptions>([](FrameOptions& f) -> auto& { return f.camera; }),
                   viewFlag(), o.view);
    if (!settings.dsm.lights.empty()) settings.dsm.enabled = true;  // `--dsm-lights` alone turns them on
    validateSettings(settings);
    if (settings.aov == Aov::Velocity && settings.cameraPath == CameraPath::Gbuffer)
        fmt::print(stderr, "penumbra: warning: {} velocity with {} gbuffer shows camera motion only "
                           "(moving objects need the visibility path's triangle IDs)\n",
                   frameFlag([](RenderSettings& r) -> auto& { return r.aov; }),
                   frameFlag([](RenderSettings& r) -> auto& { return r.cameraPath; }));
    if (settings.gi == GiMode::Rsm && settings.rsm.bilinearVpls && settings.rsm.far == RsmFar::Flux &&
        settings.rsm.weights == RsmWeights::Unbiased) {
        const OptionTable& rsm = rsmOptions();
        fmt::print(stderr, "penumbra: warning: {} bilinear applies to the r_max disc's samples only: the flux "
                           "draws stay texels ({} disc for a gather continuous in the light's motion)\n",
                   rsm.flagOf<RsmSettings>([](RsmSettings& r) -> auto& { return r.bilinearVpls; }),
                   rsm.flagOf<RsmSettings>([](RsmSettings& r) -> auto& { return r.far; }));
    }
}

std::vector<Light> frameLights(const FrameOptions& o, const Scene& loaded) {
    std::vector<Light> lights = o.parsedLights;
    if (const NamedView* view = frameView(o); lights.empty() && view)
        for (const std::string& l : view->lights) lights.push_back(parseLight(l));
    if (lights.empty()) lights = loaded.lights;  // loadScene added the default sun where there is none
    try {
        applyLightFilters(o.lightFilters, lights);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(frameInputOptions().flagOf<FrameOptions>([](FrameOptions& f) -> auto& {
            return f.lightFilters;
        }) + " " + e.what());
    }
    return lights;
}

Camera frameCamera(const FrameOptions& o, const Scene& scene) {
    if (o.parsedCamera) return *o.parsedCamera;
    if (const NamedView* view = frameView(o)) return parseCamera(view->camera);
    if (o.cameraIndex < 0 || o.cameraIndex >= int(scene.cameras.size()))
        throw std::invalid_argument(fmt::format("{} {}: the scene has {} camera{}",
                                                frameInputOptions().flagOf<FrameOptions>([](FrameOptions& f) -> auto& { return f.cameraIndex; }),
                                                o.cameraIndex, scene.cameras.size(),
                                                scene.cameras.size() == 1 ? "" : "s"));
    return scene.cameras[o.cameraIndex];
}

PreparedFrame loadFrame(const FrameOptions& o) {
    PreparedFrame f;
    f.scene = loadScene(o.scene, o.builtin);
    for (const std::string& w : f.scene.warnings) printFrameWarning(w);
    if (const std::string w = planTextureTable(f.scene.textures).warning(); !w.empty())
        fmt::print(stderr, "penumbra: warning: {}\n", w);
    f.scene.lights = frameLights(o, f.scene);
    f.camera = frameCamera(o, f.scene);
    return f;
}

PreparedFrame prepareFrame(const FrameOptions& o, RenderSettings& settings) {
    checkFrameSettings(o, settings);
    PreparedFrame f = loadFrame(o);
    checkedMotion(o, f);  // the animation exists, the paths fit the scene
    return f;
}

}  // namespace penumbra
