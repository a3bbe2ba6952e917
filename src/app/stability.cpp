#include "app/stability.h"

#include <cmath>
#include <cstring>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/device_budget.h"
#include "app/option_checks.h"
#include "reference/path_tracer.h"

namespace penumbra {
namespace {

float luminance(const float* rgba) { return 0.2126f * rgba[0] + 0.7152f * rgba[1] + 0.0722f * rgba[2]; }

std::vector<float> toLuminance(const std::vector<float>& rgba) {
    std::vector<float> out(rgba.size() / 4);
    for (size_t i = 0; i < out.size(); ++i) out[i] = luminance(&rgba[i * 4]);
    return out;
}

// Camera-only motion is measured at fixed world points: the first frame's G-buffer positions, each
// looked up in frame t at the pixel it projects to (NaN where it leaves the image or is hidden).
struct WorldPoints {
    std::vector<glm::vec3> points;  // per first-frame pixel (NaN where no surface)
    uint32_t width = 0, height = 0;

    void capture(Renderer& r) {
        width = r.settings().width, height = r.settings().height;
        const std::vector<uint8_t> depth = r.commands().readImage(r.gbuffer().depth, 4);
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
    std::vector<float> sample(Renderer& r, const std::vector<float>& lum) const {
        const std::vector<uint8_t> depth = r.commands().readImage(r.gbuffer().depth, 4);
        const glm::mat4 vp = r.frameUniforms().viewProj;
        std::vector<float> out(points.size(), NAN);
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
            out[i] = lum[size_t(y) * width + x];
        }
        return out;
    }
};

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

// The path tracer's figure for the same frames, spp doubled until doubling changes it by < 5%.
nlohmann::json referenceFlicker(const StabilityOptions& o, const PreparedFrame& f, const SceneMotion& motion,
                                const RenderSettings& s) {
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
    for (uint32_t spp = o.referenceSpp; spp <= o.referenceMaxSpp; spp *= 2) {
        std::vector<std::vector<float>> fin, ind;
        for (int i = 0; i < o.frames; ++i) {
            ReferenceSettings rs;
            rs.width = s.width, rs.height = s.height, rs.spp = spp, rs.progress = false;
            rs.seed = 1 + uint64_t(i);  // independent noise per frame: what is left after convergence is motion
            const ReferenceImage img = renderReference(scenes[size_t(i)], cameras[size_t(i)], rs);
            fin.push_back(toLuminance(img.rgba(ReferenceAov::Final)));
            ind.push_back(toLuminance(img.rgba(ReferenceAov::Indirect)));
        }
        const double ff = flicker(fin), fi = flicker(ind);
        out = {{"spp", spp}, {"final_flicker", ff}, {"indirect_flicker", fi},
               {"converged", std::abs(ff - previousFinal) < 0.05 * ff && std::abs(fi - previousIndirect) < 0.05 * fi}};
        if (out["converged"].get<bool>()) break;
        previousFinal = ff, previousIndirect = fi;
    }
    return out;
}

}  // namespace

double flicker(const std::vector<std::vector<float>>& lum) {
    double diff = 0.0, sum = 0.0;
    size_t n = 0, m = 0;
    for (size_t t = 1; t + 1 < lum.size(); ++t)
        for (size_t i = 0; i < lum[t].size(); ++i) {
            const float a = lum[t - 1][i], b = lum[t][i], c = lum[t + 1][i];
            if (std::isnan(a) || std::isnan(b) || std::isnan(c)) continue;
            diff += std::abs(double(b) - 0.5 * (double(a) + double(c)));
            ++n;
        }
    for (const auto& img : lum)
        for (float v : img)
            if (!std::isnan(v)) sum += v, ++m;
    const double mean = m ? sum / double(m) : 0.0;
    return n && mean > 0.0 ? diff / double(n) / mean : 0.0;
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
    cmd->add_option("--frames", o.frames, "Frames of the motion (>= 3)")->check(CLI::Range(3, 10000));
    cmd->add_option("--fps", o.fps, "Frames per second")->check(finiteRange(1e-3, 1e4));
    cmd->add_option("--json", o.json, "Write the figures as JSON");
    cmd->add_flag("--all", o.all, "Every shadow filter and GI mode");
    cmd->add_option("--reference-spp", o.referenceSpp, "Path tracer: first spp (doubled until the figure settles)")
        ->check(CLI::Range(1, 1 << 16));
    cmd->add_option("--reference-max-spp", o.referenceMaxSpp, "Path tracer: largest spp")->check(CLI::Range(1, 1 << 20));
    cmd->add_flag_function("--no-reference", [&o](int64_t) { o.reference = false; }, "Skip the path tracer's floor");
    return cmd;
}

int runStability(const StabilityOptions& o, const vk::ContextOptions& vkOptions, RenderSettings settings, bool dryRun) {
    if (!o.json.empty()) checkWritable(o.json, "--json");
    if (dryRun) return prepareFrame(o.frame, settings), 0;
    DeviceFrame device(o.frame, settings, vkOptions);
    const PreparedFrame& f = device.frame;
    const SceneMotion motion = frameMotion(o.frame, f);
    if (!motion.moves())
        fmt::print(stderr, "penumbra: warning: nothing in '{}' moves: give --sun-path, --light-path or --camera-keys\n",
                   f.scene.name);
    GpuScene scene(device.ctx, f.scene);
    const bool atWorldPoints = motion.cameraMoves();
    nlohmann::json results = nlohmann::json::array();
    fmt::print("{:<14} {:>14} {:>17}\n", "technique", "final flicker", "indirect flicker");
    for (const Config& c : configs(settings, o.all)) {
        std::vector<std::vector<float>> fin, ind;
        WorldPoints points;
        Renderer r(device.ctx, scene, c.settings, 1);
        for (int i = 0; i < o.frames; ++i) {
            const FrameInputs in = frameInputs(motion, o.frame.time + i / o.fps);
            for (Aov aov : {Aov::Final, Aov::Indirect}) {
                if (aov == Aov::Indirect && c.settings.gi == GiMode::None) continue;
                r.setAov(aov);
                r.render(in);
                std::vector<float> lum = toLuminance(r.readHdr());
                if (atWorldPoints && i == 0) points.capture(r);
                if (atWorldPoints) lum = points.sample(r, lum);
                (aov == Aov::Final ? fin : ind).push_back(std::move(lum));
            }
        }
        nlohmann::json j{{"technique", c.name}, {"final_flicker", flicker(fin)}};
        if (!ind.empty()) j["indirect_flicker"] = flicker(ind);
        fmt::print("{:<14} {:>14.5f} {:>17}\n", c.name, flicker(fin),
                   ind.empty() ? std::string("-") : fmt::format("{:.5f}", flicker(ind)));
        results.push_back(j);
    }
    nlohmann::json out{{"command", o.command}, {"scene", f.scene.name}, {"frames", o.frames}, {"fps", o.fps},
                       {"start_time", o.frame.time}, {"camera_motion_at_world_points", atWorldPoints},
                       {"width", settings.width}, {"height", settings.height}, {"techniques", results}};
    if (o.reference) {
        const nlohmann::json ref = referenceFlicker(o, f, motion, settings);
        fmt::print("{:<14} {:>14.5f} {:>17.5f}   ({} spp{})\n", "path tracer", ref["final_flicker"].get<double>(),
                   ref["indirect_flicker"].get<double>(), ref["spp"].get<uint32_t>(),
                   ref["converged"].get<bool>() ? ", settled" : ", NOT settled: the floor includes noise");
        out["reference"] = ref;
    }
    if (!o.json.empty()) std::ofstream(o.json) << out.dump(2) << "\n";
    device.checkValidation();
    return 0;
}

}  // namespace penumbra
