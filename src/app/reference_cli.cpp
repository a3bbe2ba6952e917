// `penumbra reference` and `penumbra compare` (ground_truth_cli.h).
#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/ground_truth_cli.h"
#include "eval/compare.h"
#include "io/image_io.h"
#include "lighting/lighting_options.h"
#include "app/bench.h"
#include "app/cli_app.h"
#include "app/option_checks.h"
#include "app/option_cli.h"

namespace penumbra {
namespace {

std::string fmtMetric(double v) {
    return std::isfinite(v) ? fmt::format("{:.6g}", v) : std::string(std::isnan(v) ? "nan" : "inf");
}

nlohmann::json jsonNumber(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace

namespace {

using change::kCommand;

// `quiet` rows: on when given bare, writing `progress` (its opposite).
template <class S, class Access>
OptionRow& quietRow(OptionTableBuilder<S>& t, Access progress, const char* help) {
    OptionRow& row = t.text(
        sharedFlag<RenderCliOptions>(renderCommandOptions(), [](RenderCliOptions& r) -> auto& { return r.quiet; }),
        "quiet", progress, [progress](const S& s) { return std::vector<std::string>{progress(const_cast<S&>(s)) ? "off" : "on"}; },
        [progress](S& s, const std::string& v) {
            if (v != "on" && v != "off") throw std::invalid_argument("expected on or off");
            progress(s) = v == "off";
        },
        kCommand, help);
    row.bareFlag = true;
    return row;
}

OptionTable makeReferenceSceneTable() {
    using R = ReferenceCliOptions;
    OptionTableBuilder<R> t("reference_scene", "Reference: size and sampling");
    t.integer(sharedFlag<RenderSettings>(frameOptionTable(), [](RenderSettings& s) -> auto& { return s.width; }), "width",
              [](R& r) -> auto& { return r.settings.width; }, 1, 16384, kCommand, "Image width");
    t.integer(sharedFlag<RenderSettings>(frameOptionTable(), [](RenderSettings& s) -> auto& { return s.height; }),
              "height", [](R& r) -> auto& { return r.settings.height; }, 1, 16384, kCommand, "Image height");
    t.integer("--spp", "spp", [](R& r) -> auto& { return r.settings.spp; }, 1, 1 << 20, kCommand, "Paths per pixel");
    t.integer("--bounces", "bounces", [](R& r) -> auto& { return r.settings.bounces; }, 0, kMaxReferenceBounces,
              kCommand, "Diffuse bounces (1: what RSM and LPV approximate)");
    t.integer("--seed", "seed", [](R& r) -> auto& { return r.settings.seed; }, 0, 9007199254740992.0, kCommand,
              "Random seed (the image is a function of it)");
    t.integer("--threads", "threads", [](R& r) -> auto& { return r.settings.threads; }, 1, 1024, kCommand,
              "Worker threads")
        .orSpecial(0, "every hardware thread");
    t.boolean("--aa", "aa", [](R& r) -> auto& { return r.settings.antialias; }, kCommand,
              "Spread paths over the pixel (default: its centre, as the rasterizer)")
        .bareFlag = true;
    quietRow(t, [](R& r) -> auto& { return r.settings.progress; }, "No progress bar and no summary");
    return t.build();
}

OptionTable makeReferenceCommandTable() {
    using R = ReferenceCliOptions;
    OptionTableBuilder<R> t("reference", "Reference");
    t.text(sharedFlag<RenderCliOptions>(renderCommandOptions(), [](RenderCliOptions& r) -> auto& { return r.output; }),
           "output", [](R& r) -> auto& { return r.output; },
           [](const R& r) { return std::vector<std::string>{r.output}; }, [](R& r, const std::string& v) { r.output = v; },
           kCommand, "Output image: .exr (linear) or .png (tone-mapped)")
        .placeholder = "FILE";
    t.choice(sharedFlag<RenderSettings>(frameOptionTable(), [](RenderSettings& s) -> auto& { return s.aov; }), "aov",
             [](R& r) -> auto& { return r.aov; },
             std::vector<std::pair<std::string, ReferenceAov>>{{"final", ReferenceAov::Final},
                                                                {"direct", ReferenceAov::Direct},
                                                                {"indirect", ReferenceAov::Indirect},
                                                                {"mask", ReferenceAov::Mask},
                                                                {"shadow", ReferenceAov::Shadow},
                                                                {"hair", ReferenceAov::Hair}},
             kCommand,
             "final (direct + indirect), direct, indirect, mask (1 on geometry), shadow (the first shadowed light's "
             "visibility at the opaque surface, as render's), hair (fraction of paths stopping at a strand)");
    t.real(sharedFlag<RenderSettings>(frameOptionTable(), [](RenderSettings& s) -> auto& { return s.exposure; }),
           "exposure", [](R& r) -> auto& { return r.exposure; }, 1e-6, 1e6, kCommand,
           "PNG only: linear multiplier before tone mapping");
    return t.build();
}

OptionTable makeCompareCommandTable() {
    using C = CompareCliOptions;
    OptionTableBuilder<C> t("compare", "Compare");
    t.text("--mask", "mask", [](C& c) -> auto& { return c.mask; },
           [](const C& c) { return c.mask.empty() ? std::vector<std::string>{} : std::vector<std::string>{c.mask}; },
           [](C& c, const std::string& v) { c.mask = v; }, kCommand,
           "EXR or PNG of the same size: only its non-zero pixels are compared")
        .placeholder = "FILE";
    t.text(sharedFlag<RenderCliOptions>(renderCommandOptions(), [](RenderCliOptions& r) -> auto& { return r.output; }),
           "heat_map", [](C& c) -> auto& { return c.heatMap; },
           [](const C& c) { return c.heatMap.empty() ? std::vector<std::string>{} : std::vector<std::string>{c.heatMap}; },
           [](C& c, const std::string& v) { c.heatMap = v; }, kCommand,
           "Heat map of |luminance(A) - luminance(B)| (PNG)")
        .placeholder = "FILE";
    t.real("--heat-max", "heat_max", [](C& c) -> auto& { return c.heatMax; }, 1e-30, 1e30, kCommand,
           "Error at the top of the heat map")
        .orSpecial(0, "the 99th percentile of the error");
    t.boolean(sharedFlag<BenchOptions>(benchCommandOptions(), [](BenchOptions& b) -> auto& { return b.json; }), "json",
              [](C& c) -> auto& { return c.json; }, kCommand, "Print the metrics as JSON")
        .bareFlag = true;
    return t.build();
}

}  // namespace

const OptionTable& referenceSceneOptions() {
    static const OptionTable table = makeReferenceSceneTable();
    return table;
}

const OptionTable& referenceCommandOptions() {
    static const OptionTable table = makeReferenceCommandTable();
    return table;
}

const OptionTable& compareCommandOptions() {
    static const OptionTable table = makeCompareCommandTable();
    return table;
}

void addReferenceSceneOptions(CLI::App& cmd, ReferenceCliOptions& o) {
    cmd.add_option("scene", o.frame.scene, "glTF file (.gltf/.glb) or built-in scene");
    addOptionRows(cmd, referenceSceneOptions(), &o);
    // The frame inputs the path tracer honours: every one but the per-light shadow filter.
    const std::string& lightShadow = frameInputOptions().flagOf<FrameOptions>([](FrameOptions& f) -> auto& {
        return f.lightFilters;
    });
    addOptionRows(cmd, frameInputOptions(), &o.frame, [&lightShadow](const OptionRow& r) { return r.flag != lightShadow; });
    addMotionOptions(cmd, o.frame);
}

PreparedFrame prepareReferenceFrame(const ReferenceCliOptions& o) {
    RenderSettings unused;
    checkFrameSettings(o.frame, unused);
    PreparedFrame f = loadFrame(o.frame);
    // The scene at --time: the path tracer traces its world-space geometry at that time.
    const SceneMotion motion = frameMotion(o.frame, f);
    if (motion.moves()) {
        ScenePose pose = motion.at(o.frame.time);
        Scene world = worldSpaceScene(f.scene, pose.instances);
        world.lights = std::move(pose.lights);
        f.scene = std::move(world);
        f.camera = pose.camera;
    }
    return f;
}

CLI::App* addReferenceCommand(CLI::App& app, ReferenceCliOptions& o) {
    CLI::App* cmd = app.add_subcommand("reference", "Path-trace the ground truth on the CPU (Embree): EXR radiance");
    addReferenceSceneOptions(*cmd, o);
    addOptionRows(*cmd, referenceCommandOptions(), &o);
    addOptionRows(*cmd, lightingOptions(), &o.lighting);  // the sky, as `render` takes it
    return cmd;
}

int runReferenceCommand(const ReferenceCliOptions& o, bool dryRun) {
    const std::string ext = fileExtension(o.output);
    if (ext != ".exr" && ext != ".png")
        throw std::invalid_argument(fmt::format("-o {}: the output must end in .exr or .png", o.output));
    checkWritable(o.output, "-o");
    const ReferenceAov aov = o.aov;
    PreparedFrame f = prepareReferenceFrame(o);
    if (dryRun) return 0;
    ReferenceSettings settings = o.settings;
    settings.sky = o.lighting.sky;
    resolveAutoSky(settings.sky, f.scene.lights);
    const ReferenceImage img = renderReference(f.scene, f.camera, settings);
    for (const std::string& w : img.warnings) printWarning(w);
    const ImageF out{img.width, img.height, img.rgba(aov)};
    if (ext == ".exr") writeExr(o.output, out.width, out.height, out.rgba);
    else writePng(o.output, out.width, out.height, toneMap(out, o.exposure));
    if (o.settings.progress)
        fmt::print("penumbra: reference '{}' ({} triangles, {}{}) {}x{}, {} paths/pixel, {} bounce(s): "
                   "{:.1f} s, {:.1f} M rays/s -> {}\n",
                   f.scene.name, f.scene.triangleCount(),
                   f.scene.strands.empty() ? "" : fmt::format("{} strands, ", f.scene.strands.size()),
                   plural(f.scene.lights.size(), "light"), img.width, img.height, img.spp,
                   o.settings.bounces, img.seconds, double(img.rays) / img.seconds * 1e-6, o.output);
    return 0;
}

CLI::App* addCompareCommand(CLI::App& app, CompareCliOptions& o) {
    CLI::App* cmd = app.add_subcommand("compare", "Error of image A against reference B (EXR): RMSE, relative L1/L2, "
                                                  "bias, max, SSIM; heat map");
    cmd->add_option("A", o.a, "Test image (EXR)")->required();
    cmd->add_option("B", o.b, "Reference image (EXR)")->required();
    addOptionRows(*cmd, compareCommandOptions(), &o);
    return cmd;
}

int runCompareCommand(const CompareCliOptions& o, bool dryRun) {
    if (!o.heatMap.empty() && fileExtension(o.heatMap) != ".png")
        throw std::invalid_argument(fmt::format("-o {}: the heat map must end in .png", o.heatMap));
    if (!o.heatMap.empty()) checkWritable(o.heatMap, "-o");
    const ImageF a = readExrChecked(o.a, "A");
    const ImageF b = readExrChecked(o.b, "B");
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument(
            fmt::format("A {} is {}x{}, B {} is {}x{}: the sizes must match", o.a, a.width, a.height, o.b, b.width,
                        b.height));
    const std::vector<uint8_t> mask = o.mask.empty() ? std::vector<uint8_t>{} : loadMask(o.mask, compareCommandOptions().flagOf<CompareCliOptions>([](CompareCliOptions& c) -> auto& { return c.mask; }), a.width, a.height);
    if (dryRun) return 0;
    const ImageMetrics m = compareImages(a, b, mask);
    double scale = o.heatMax;
    if (!o.heatMap.empty()) writePng(o.heatMap, a.width, a.height, errorHeatMap(a, b, mask, scale));
    if (o.json) {
        nlohmann::json j{{"a", o.a}, {"b", o.b}, {"pixels", m.pixels}, {"rmse", jsonNumber(m.rmse)},
                         {"rel_l1", jsonNumber(m.relL1)}, {"rel_l2", jsonNumber(m.relL2)},
                         {"mean_bias", jsonNumber(m.meanBias)},
                         {"relative_bias", jsonNumber(m.refMean > 0.0 ? m.meanBias / m.refMean : NAN)},
                         {"max_error", jsonNumber(m.maxError)}, {"differing_pixels", m.differing},
                         {"ssim", jsonNumber(m.ssim)}, {"ssim_range", jsonNumber(m.ssimRange)},
                         {"ssim_window", fmt::format("{0}x{0} Gaussian, sigma {1}", kSsimWindow, kSsimSigma)}};
        if (!o.mask.empty()) j["mask"] = o.mask;
        if (!o.heatMap.empty()) j["heat_map"] = {{"path", o.heatMap}, {"max", scale}};
        fmt::print("{}\n", j.dump(2));
        return 0;
    }
    fmt::print("compared {} pixels{} of {}x{}\n", m.pixels, o.mask.empty() ? "" : " (mask)", a.width, a.height);
    fmt::print("  rmse        {}\n  rel L1      {}\n  rel L2      {}\n  mean bias   {} (A - B; relative {})\n"
               "  max error   {}\n",
               fmtMetric(m.rmse), fmtMetric(m.relL1), fmtMetric(m.relL2), fmtMetric(m.meanBias),
               fmtMetric(m.refMean > 0.0 ? m.meanBias / m.refMean : NAN), fmtMetric(m.maxError));
    fmt::print("  differing   {} pixels ({:.4f}%) off by more than {} in a channel\n", m.differing,
               100.0 * double(m.differing) / double(m.pixels), kDifferingError);
    fmt::print("  SSIM        {} (luminance, {}x{} Gaussian window, sigma {}, L = {})\n", fmtMetric(m.ssim),
               kSsimWindow, kSsimWindow, kSsimSigma, fmtMetric(m.ssimRange));
    if (!o.heatMap.empty())
        fmt::print("heat map {}: |Y(A) - Y(B)|, black = 0 .. pale yellow = {} and above\n", o.heatMap,
                   fmtMetric(scale));
    return 0;
}

}  // namespace penumbra
