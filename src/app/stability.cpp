#include "app/stability.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <memory>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/bench.h"
#include "app/cli_app.h"
#include "app/ghosting.h"
#include "app/option_checks.h"
#include "app/option_cli.h"
#include "app/response.h"
#include "frame/frame_setup.h"
#include "io/file_write.h"
#include "lighting/lighting_technique.h"
#include "reference/path_tracer.h"
#include "renderer/render_options.h"

namespace penumbra {
namespace {

float luminance(const float* rgba) { return 0.2126f * rgba[0] + 0.7152f * rgba[1] + 0.0722f * rgba[2]; }

std::vector<float> toLuminance(const std::vector<float>& rgba) {
    std::vector<float> out(rgba.size() / 4);
    for (size_t i = 0; i < out.size(); ++i) out[i] = luminance(&rgba[i * 4]);
    return out;
}

// Camera-only motion is measured at fixed world points: the first frame's G-buffer positions, each
// looked up in frame t at the pixel it projects to (NaN where it leaves the image or is hidden). The
// lookups of each frame are kept (`maps`), so that the path tracer's frames are read at the same pixels.
struct WorldPoints {
    std::vector<glm::vec3> points;  // per first-frame pixel (NaN where no surface)
    uint32_t width = 0, height = 0;
    std::vector<std::vector<int64_t>> maps;  // per frame: per first-frame pixel, the pixel read (-1: none)

    void capture(Renderer& r) {
        width = r.settings().width, height = r.settings().height;
        const std::vector<uint8_t> depth = r.commands().readImage(r.find<CameraTechnique>()->gbuffer().depth, 4);
        const glm::mat4 inv = r.frameUniforms().invViewProj;
        points.assign(size_t(width) * height, glm::vec3(NAN));
        for (size_t i = 0; i < points.size(); ++i) {
            float d;
            std::memcpy(&d, depth.data() + i * 4, 4);
            if (d >= 1.0f) continue;
            const glm::vec4 p = inv * glm::vec4((float(i % width) + 0.5f) / width * 2 - 1,
                                                (float(i / width) + 0.5f) / height * 2 - 1, d, 1.0f);
            points[i] = glm::vec3(p) / p.w;
        }
    }
    // The pixel of frame `r` that shows each point (-1: off the image or hidden).
    std::vector<int64_t> lookups(Renderer& r) const {
        const std::vector<uint8_t> depth = r.commands().readImage(r.find<CameraTechnique>()->gbuffer().depth, 4);
        const glm::mat4 vp = r.frameUniforms().viewProj;
        std::vector<int64_t> out(points.size(), -1);
        for (size_t i = 0; i < points.size(); ++i) {
            if (std::isnan(points[i].x)) continue;
            const glm::vec4 c = vp * glm::vec4(points[i], 1.0f);
            if (c.w <= 0.0f) continue;
            const glm::vec3 ndc = glm::vec3(c) / c.w;
            const int x = int(std::floor((ndc.x * 0.5f + 0.5f) * width)), y = int(std::floor((ndc.y * 0.5f + 0.5f) * height));
            if (x < 0 || y < 0 || x >= int(width) || y >= int(height)) continue;
            float d;
            std::memcpy(&d, depth.data() + (size_t(y) * width + x) * 4, 4);
            if (std::abs(d - ndc.z) > 1e-3f * std::max(1e-3f, 1.0f - ndc.z) * 50.0f) continue;  // hidden in frame t
            out[i] = int64_t(y) * width + x;
        }
        return out;
    }
};

std::vector<float> sampleAt(const std::vector<int64_t>& map, const std::vector<float>& lum) {
    std::vector<float> out(map.size(), NAN);
    for (size_t i = 0; i < map.size(); ++i)
        if (map[i] >= 0) out[i] = lum[size_t(map[i])];
    return out;
}

// The second differences I_t - (I_{t-1} + I_{t+1}) / 2 of every interior frame and measured pixel,
// and the mean of I: what both flicker figures are made of.
struct SecondDifferences {
    std::vector<double> d;
    double mean = 0.0;
};

SecondDifferences secondDifferences(const std::vector<std::vector<float>>& lum) {
    SecondDifferences out;
    double sum = 0.0;
    size_t m = 0;
    for (size_t t = 1; t + 1 < lum.size(); ++t)
        for (size_t i = 0; i < lum[t].size(); ++i) {
            const float a = lum[t - 1][i], b = lum[t][i], c = lum[t + 1][i];
            out.d.push_back(std::isnan(a) || std::isnan(b) || std::isnan(c) ? NAN : double(b) - 0.5 * (double(a) + double(c)));
        }
    for (const auto& img : lum)
        for (float v : img)
            if (!std::isnan(v)) sum += v, ++m;
    out.mean = m ? sum / double(m) : 0.0;
    return out;
}

struct Config {
    std::string name;
    RenderSettings settings;
};

std::vector<Config> configs(const RenderSettings& base, bool all) {
    std::vector<Config> out;
    auto name = [](const RenderSettings& s) {
        static const char* filters[] = {"default", "hard", "pcf", "pcss", "vsm", "evsm", "msm"};
        static const char* gis[] = {"none", "rsm", "lpv"};
        return fmt::format("{}+{}", filters[uint32_t(s.shadow.filter)], gis[uint32_t(s.gi)]);
    };
    out.push_back({name(base), base});
    if (!all) return out;
    for (ShadowFilter f : {ShadowFilter::Hard, ShadowFilter::Pcf, ShadowFilter::Pcss, ShadowFilter::Vsm,
                           ShadowFilter::Evsm, ShadowFilter::Msm}) {
        RenderSettings s = base;
        s.shadow.filter = f;
        if (f != base.shadow.filter) out.push_back({name(s), s});
    }
    for (GiMode g : {GiMode::None, GiMode::Rsm, GiMode::Lpv}) {
        RenderSettings s = base;
        s.gi = g;
        if (g != base.gi) out.push_back({name(s), s});
    }
    return out;
}

// The path tracer's frames at `spp` (luminance of the final image and of the indirect light), read
// at the world points' pixels when `maps` is given; `seedBase` makes every frame's noise its own.
struct ReferenceFrames {
    std::vector<std::vector<float>> final, indirect;
};

ReferenceFrames referenceFrames(const std::vector<Scene>& scenes, const std::vector<Camera>& cameras,
                                const RenderSettings& s, uint32_t spp, uint64_t seedBase,
                                const std::vector<std::vector<int64_t>>& maps) {
    ReferenceFrames out;
    for (size_t i = 0; i < scenes.size(); ++i) {
        ReferenceSettings rs;
        rs.width = s.width, rs.height = s.height, rs.spp = spp, rs.progress = false;
        rs.seed = seedBase + i;
        const ReferenceImage img = renderReference(scenes[i], cameras[i], rs);
        std::vector<float> fin = toLuminance(img.rgba(ReferenceAov::Final)), ind = toLuminance(img.rgba(ReferenceAov::Indirect));
        out.final.push_back(maps.empty() ? std::move(fin) : sampleAt(maps[i], fin));
        out.indirect.push_back(maps.empty() ? std::move(ind) : sampleAt(maps[i], ind));
    }
    return out;
}

// The path tracer's figures for the same frames. The L1 figure: spp doubled until doubling changes it
// by < 5% (its noise adds to it). The RMS figure with the noise removed: two renders of every frame
// with independent seeds give second differences D_a = D + e_a and D_b = D + e_b, and the mean of
// D_a * D_b estimates the mean of D^2 without bias (the noises are independent with mean 0).
nlohmann::json referenceFlicker(const StabilityOptions& o, const PreparedFrame& f, const SceneMotion& motion,
                                const RenderSettings& s, const std::vector<std::vector<int64_t>>& maps) {
    std::vector<Scene> scenes;
    std::vector<Camera> cameras;
    for (int i = 0; i < o.frames; ++i) {
        ScenePose pose = motion.at(o.frame.time + i / o.fps);
        scenes.push_back(worldSpaceScene(f.scene, pose.instances));
        scenes.back().lights = pose.lights;
        cameras.push_back(pose.camera);
    }
    double previousFinal = NAN, previousIndirect = NAN;
    nlohmann::json out;
    ReferenceFrames a;
    uint32_t spp = o.referenceSpp;
    for (;; spp *= 2) {
        a = referenceFrames(scenes, cameras, s, spp, 1, maps);
        const double ff = flicker(a.final), fi = flicker(a.indirect);
        out = {{"spp", spp}, {"final_flicker", ff}, {"indirect_flicker", fi},
               {"converged", std::abs(ff - previousFinal) < 0.05 * ff && std::abs(fi - previousIndirect) < 0.05 * fi}};
        if (out["converged"].get<bool>() || spp * 2 > o.referenceMaxSpp) break;
        previousFinal = ff, previousIndirect = fi;
    }
    const ReferenceFrames b = referenceFrames(scenes, cameras, s, spp, 1 + uint64_t(o.frames), maps);
    out["final_flicker_rms_noise_free"] = flickerRmsNoiseFree(a.final, b.final);
    out["indirect_flicker_rms_noise_free"] = flickerRmsNoiseFree(a.indirect, b.indirect);
    out["final_flicker_rms"] = flickerRms(a.final);
    out["indirect_flicker_rms"] = flickerRms(a.indirect);
    return out;
}

}  // namespace

double flicker(const std::vector<std::vector<float>>& lum) {
    const SecondDifferences s = secondDifferences(lum);
    double diff = 0.0;
    size_t n = 0;
    for (double d : s.d)
        if (!std::isnan(d)) diff += std::abs(d), ++n;
    return n && s.mean > 0.0 ? diff / double(n) / s.mean : 0.0;
}

double flickerRms(const std::vector<std::vector<float>>& lum) { return flickerRmsNoiseFree(lum, lum); }

double flickerRmsNoiseFree(const std::vector<std::vector<float>>& a, const std::vector<std::vector<float>>& b) {
    const SecondDifferences sa = secondDifferences(a), sb = secondDifferences(b);
    double product = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < sa.d.size() && i < sb.d.size(); ++i)
        if (!std::isnan(sa.d[i]) && !std::isnan(sb.d[i])) product += sa.d[i] * sb.d[i], ++n;
    const double mean = 0.5 * (sa.mean + sb.mean);
    return n && mean > 0.0 ? std::sqrt(std::max(product / double(n), 0.0)) / mean : 0.0;
}

namespace {

using change::kCommand;

OptionTable makeStabilityCommandTable() {
    using S = StabilityOptions;
    OptionTableBuilder<S> t("stability", "Stability");
    t.integer(sharedFlag<BenchOptions>(benchCommandOptions(), [](BenchOptions& b) -> auto& { return b.frames; }),
              "frames", [](S& s) -> auto& { return s.frames; }, 3, 10000, kCommand, "Frames of the motion");
    t.integer(sharedFlag<BenchOptions>(benchCommandOptions(), [](BenchOptions& b) -> auto& { return b.warmup; }),
              "warmup", [](S& s) -> auto& { return s.warmup; }, 0, 100000, kCommand,
              "Still frames at the motion's start before the measured ones (the GI history settles)");
    t.real(sharedFlag<RenderCliOptions>(renderCommandOptions(), [](RenderCliOptions& r) -> auto& { return r.fps; }),
           "fps", [](S& s) -> auto& { return s.fps; }, 1e-3, 1e4, kCommand, "Frames per second");
    t.text(sharedFlag<BenchOptions>(benchCommandOptions(), [](BenchOptions& b) -> auto& { return b.json; }), "json",
           [](S& s) -> auto& { return s.json; },
           [](const S& s) { return s.json.empty() ? std::vector<std::string>{} : std::vector<std::string>{s.json}; },
           [](S& s, const std::string& v) { s.json = v; }, kCommand, "Write the figures as JSON")
        .placeholder = "FILE";
    t.boolean("--all", "all", [](S& s) -> auto& { return s.all; }, kCommand, "Every shadow filter and GI mode")
        .bareFlag = true;
    t.integer("--reference-spp", "reference_spp", [](S& s) -> auto& { return s.referenceSpp; }, 1, 1 << 16, kCommand,
              "Path tracer: first spp (doubled until the figure settles)");
    t.integer("--reference-max-spp", "reference_max_spp", [](S& s) -> auto& { return s.referenceMaxSpp; }, 1, 1 << 20,
              kCommand, "Path tracer: largest spp");
    t.text("--no-reference", "no_reference", [](S& s) -> auto& { return s.reference; },
           [](const S& s) { return std::vector<std::string>{s.reference ? "off" : "on"}; },
           [](S& s, const std::string& v) {
               if (v != "on" && v != "off") throw std::invalid_argument("expected on or off");
               s.reference = v == "off";
           },
           kCommand, "Skip the path tracer's floor")
        .bareFlag = true;
    t.text("--change", "change", [](S& s) -> auto& { return s.change; },
           [](const S& s) { return s.change.empty() ? std::vector<std::string>{} : std::vector<std::string>{s.change}; },
           [](S& s, const std::string& v) {
               parseLightChange(v);
               s.change = v;
           },
           kCommand,
           "Measure the GI's response to a sudden change instead of flicker: sun:DEG (every directional light's "
           "direction turns DEG degrees, its elevation changing), off or on (the first light); r_k for k = 1 ... "
           "frames")
        .placeholder = "sun:DEG|off|on";
    t.integer("--settle", "settle", [](S& s) -> auto& { return s.settle; }, 1, 100000, kCommand,
              "With {stability.change}: still frames before the change and after it; with {stability.ghosting}: of each "
              "instant's still image (the converged images)");
    t.boolean("--ghosting", "ghosting", [](S& s) -> auto& { return s.ghosting; }, kCommand,
              "Measure the GI's ghosting instead of flicker: over the pixels that moving geometry covered two frames "
              "earlier and no longer covers, the indirect light against the converged still image of that instant, "
              "at each of the measured frames after the warm-up (a scene with an animation: cornell-moving)")
        .bareFlag = true;
    return t.build();
}

// The response of each GI configuration to o.change, measured on the indirect light.
int runResponse(const StabilityOptions& o, OptionsDeviceFrame& device, const SceneMotion& motion, GpuScene& scene,
                const RenderSettings& settings) {
    const LightChange change = parseLightChange(o.change);
    const FrameInputs in = frameInputs(motion, o.frame.time);
    nlohmann::json results = nlohmann::json::array();
    fmt::print("{:<14} {:>8} {:>8} {:>8} {:>8} {:>8}\n", "technique", "pixels", "r_1", "r_2", "r_2 p05", "r_8");
    for (const Config& c : configs(settings, o.all)) {
        if (c.settings.gi == GiMode::None) continue;
        RenderSettings s = c.settings;
        s.aov = Aov::Indirect;
        Renderer r(device.ctx, scene, s, 1);
        nlohmann::json j = measureResponse(r, in.camera, change, in.lights, o.settle, o.frames);
        const auto at = [&](size_t k, const char* key) {
            return k <= j["r"].size() ? fmt::format("{:.3f}", j["r"][k - 1][key].get<double>()) : std::string("-");
        };
        fmt::print("{:<14} {:>8} {:>8} {:>8} {:>8} {:>8}\n", c.name, j["pixels_changed"].get<size_t>(),
                   at(1, "median"), at(2, "median"), at(2, "p05"), at(8, "median"));
        j["technique"] = c.name;
        j["settings"] = renderSettingsJson(c.settings);
        results.push_back(j);
    }
    const nlohmann::json out{{"command", o.command}, {"scene", device.frame.scene.name}, {"change", o.change},
                             {"settle", o.settle}, {"width", settings.width}, {"height", settings.height},
                             {"techniques", results}};
    if (!o.json.empty()) writeTextFile(o.json, out.dump(2));
    device.checkValidation();
    return 0;
}

// The ghosting of each GI configuration behind the scene's moving geometry.
int runGhosting(const StabilityOptions& o, OptionsDeviceFrame& device, const SceneMotion& motion, GpuScene& scene,
                const RenderSettings& settings) {
    nlohmann::json results = nlohmann::json::array();
    fmt::print("{:<14} {:>8} {:>8} {:>12}\n", "technique", "pixels", "rel L1", "beyond 10%");
    for (const Config& c : configs(settings, o.all)) {
        if (c.settings.gi == GiMode::None) continue;
        RenderSettings s = c.settings;
        s.aov = Aov::Indirect;
        nlohmann::json j = measureGhosting(device.ctx, scene, s, motion, {o.frame.time, o.fps, o.warmup, o.frames, o.settle});
        fmt::print("{:<14} {:>8} {:>8.4f} {:>12.4f}\n", c.name, j["pixels"].get<size_t>(), j["rel_l1"].get<double>(),
                   j["share_beyond_10_percent"].get<double>());
        j["technique"] = c.name;
        j["settings"] = renderSettingsJson(c.settings);
        results.push_back(j);
    }
    const nlohmann::json out{{"command", o.command}, {"scene", device.frame.scene.name}, {"fps", o.fps},
                             {"warmup", o.warmup}, {"frames", o.frames}, {"settle", o.settle},
                             {"width", settings.width}, {"height", settings.height}, {"techniques", results}};
    if (!o.json.empty()) writeTextFile(o.json, out.dump(2));
    device.checkValidation();
    return 0;
}

}  // namespace

const OptionTable& stabilityCommandOptions() {
    static const OptionTable table = makeStabilityCommandTable();
    return table;
}

CLI::App* addStabilityCommand(CLI::App& app, StabilityOptions& o, RenderSettings& rs) {
    CLI::App* cmd = app.add_subcommand("stability", "Temporal flicker of the techniques over a slow motion, with the "
                                                    "path tracer's figure as the floor");
    addFrameOptions(*cmd, o.frame, rs);
    rs.width = 128, rs.height = 96;  // small defaults: cornell at 6 frames takes seconds on lavapipe
    rs.shadow.resolution = 512;
    rs.rsm.resolution = 256;
    rs.lpv.rsmResolution = 512;
    rs.lpv.vplResolution = 128;
    addOptionRows(*cmd, stabilityCommandOptions(), &o);
    return cmd;
}

int runStability(const StabilityOptions& o, const vk::ContextOptions& vkOptions, RenderSettings settings, bool dryRun) {
    if (!o.json.empty()) checkWritable(o.json, stabilityCommandOptions().flagOf<StabilityOptions>([](StabilityOptions& s) -> auto& { return s.json; }));
    if (o.ghosting && !o.change.empty()) throw std::invalid_argument("{stability.ghosting} and {stability.change} measure different things: give one");
    if (dryRun) return prepareFrame(o.frame, settings), 0;
    OptionsDeviceFrame device(o.frame, settings, vkOptions);
    if (o.ghosting && device.frame.scene.animations.empty())
        throw std::invalid_argument(fmt::format("{{stability.ghosting}} needs moving geometry: '{}' has no animation (try cornell-moving)",
                                                device.frame.scene.name));
    const PreparedFrame& f = device.frame;
    const SceneMotion& motion = frameMotion(o.frame, device);
    if (!motion.moves() && o.change.empty())
        fmt::print(stderr, "penumbra: warning: nothing in '{}' moves: give {}, {} or {}\n", f.scene.name,
                   motionOptions().flagOf<FrameOptions>([](FrameOptions& m) -> auto& { return m.motion.sun; }),
                   motionOptions().flagOf<FrameOptions>([](FrameOptions& m) -> auto& { return m.motion.lights; }),
                   motionOptions().flagOf<FrameOptions>([](FrameOptions& m) -> auto& { return m.motion.camera; }));
    GpuScene scene(device.ctx, f.scene);
    if (!o.change.empty()) return runResponse(o, device, motion, scene, settings);
    if (o.ghosting) return runGhosting(o, device, motion, scene, settings);
    const bool atWorldPoints = motion.cameraMoves();
    nlohmann::json results = nlohmann::json::array();
    fmt::print("{:<14} {:>13} {:>13}   {:>10} {:>12}\n", "technique", "final (L1)", "indirect (L1)", "final RMS",
               "indirect RMS");
    WorldPoints points;  // the first configuration's: the geometry is the same in all
    for (const Config& c : configs(settings, o.all)) {
        std::vector<std::vector<float>> fin, ind;
        // One renderer per image, so that each frame time adds one frame to each one's GI history.
        std::vector<std::pair<Aov, std::unique_ptr<Renderer>>> renderers;
        for (Aov aov : {Aov::Final, Aov::Indirect}) {
            if (aov == Aov::Indirect && c.settings.gi == GiMode::None) continue;
            RenderSettings s = c.settings;
            s.aov = aov;
            renderers.emplace_back(aov, std::make_unique<Renderer>(device.ctx, scene, s, 1));
        }
        for (int i = -o.warmup; i < o.frames; ++i) {
            const FrameInputs in = frameInputs(motion, o.frame.time + std::max(i, 0) / o.fps);
            for (auto& [aov, r] : renderers) {
                r->render(in);
                if (i < 0) continue;
                std::vector<float> lum = toLuminance(r->readHdr());
                if (atWorldPoints && points.points.empty()) points.capture(*r);
                if (atWorldPoints && points.maps.size() <= size_t(i)) points.maps.push_back(points.lookups(*r));
                if (atWorldPoints) lum = sampleAt(points.maps[size_t(i)], lum);
                (aov == Aov::Final ? fin : ind).push_back(std::move(lum));
            }
        }
        nlohmann::json j{{"technique", c.name}, {"settings", renderSettingsJson(c.settings)},
                         {"final_flicker", flicker(fin)}, {"final_flicker_rms", flickerRms(fin)}};
        if (!ind.empty()) j["indirect_flicker"] = flicker(ind), j["indirect_flicker_rms"] = flickerRms(ind);
        const auto cell = [&](const std::vector<std::vector<float>>& v, double (*figure)(const std::vector<std::vector<float>>&)) {
            return v.empty() ? std::string("-") : fmt::format("{:.5f}", figure(v));
        };
        fmt::print("{:<14} {:>13} {:>13}   {:>10} {:>12}\n", c.name, cell(fin, flicker), cell(ind, flicker),
                   cell(fin, flickerRms), cell(ind, flickerRms));
        results.push_back(j);
    }
    nlohmann::json out{{"command", o.command}, {"scene", f.scene.name}, {"frames", o.frames}, {"warmup", o.warmup}, {"fps", o.fps},
                       {"start_time", o.frame.time}, {"camera_motion_at_world_points", atWorldPoints},
                       {"width", settings.width}, {"height", settings.height}, {"techniques", results}};
    if (o.reference) {
        const nlohmann::json ref = referenceFlicker(o, f, motion, settings, points.maps);
        fmt::print("{:<14} {:>13.5f} {:>13.5f}   {:>10.5f} {:>12.5f}   ({} spp; L1 {}; RMS with its noise removed)\n",
                   "path tracer", ref["final_flicker"].get<double>(), ref["indirect_flicker"].get<double>(),
                   ref["final_flicker_rms_noise_free"].get<double>(), ref["indirect_flicker_rms_noise_free"].get<double>(),
                   ref["spp"].get<uint32_t>(), ref["converged"].get<bool>() ? "settled" : "NOT settled: it includes noise");
        out["reference"] = ref;
    }
    if (!o.json.empty()) writeTextFile(o.json, out.dump(2));
    device.checkValidation();
    return 0;
}

}  // namespace penumbra
