// `penumbra reference` and `penumbra compare` (ground_truth_cli.h).
#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/ground_truth_cli.h"
#include "eval/compare.h"
#include "io/image_io.h"
#include "app/option_checks.h"

namespace penumbra {
namespace {

std::string fmtMetric(double v) {
    return std::isfinite(v) ? fmt::format("{:.6g}", v) : std::string(std::isnan(v) ? "nan" : "inf");
}

nlohmann::json jsonNumber(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace

void addReferenceSceneOptions(CLI::App& cmd, ReferenceCliOptions& o) {
    cmd.add_option("scene", o.frame.scene, "glTF file (.gltf/.glb) or built-in scene");
    cmd.add_option("--width", o.settings.width, "Image width")->check(CLI::Range(1, 16384));
    cmd.add_option("--height", o.settings.height, "Image height")->check(CLI::Range(1, 16384));
    cmd.add_option("--camera", o.frame.camera, "Camera override: ex,ey,ez,tx,ty,tz,ux,uy,uz,fovy_deg");
    cmd.add_option("--camera-index", o.frame.cameraIndex, "Which of the scene's cameras to use");
    cmd.add_option("--light", o.frame.lights, "Replace the scene's lights (repeatable): see README");
    cmd.add_option("--spp", o.settings.spp, "Paths per pixel")->check(CLI::Range(1, 1 << 20));
    cmd.add_option("--bounces", o.settings.bounces, "Diffuse bounces, 0..16 (default 1, what RSM and LPV approximate)")
        ->check(CLI::Range(0u, kMaxReferenceBounces));
    cmd.add_option("--seed", o.settings.seed, "Random seed (the image is a function of it)");
    cmd.add_option("--threads", o.settings.threads, "Worker threads (default: every hardware thread)")
        ->check(CLI::Range(0, 1024));
    cmd.add_option("--strands", o.frame.builtin.hairStrands, "Hair strands of the built-in `hair` scene")
        ->check(CLI::Range(1, 2'000'000));
    cmd.add_flag("--aa", o.settings.antialias, "Spread paths over the pixel (default: its centre, as the rasterizer)");
    cmd.add_flag_function("-q,--quiet", [&o](int64_t) { o.settings.progress = false; },
                          "No progress bar and no summary");
    addMotionOptions(cmd, o.frame);
}

PreparedFrame prepareReferenceFrame(const ReferenceCliOptions& o) {
    RenderSettings unused;
    PreparedFrame f = prepareFrame(o.frame, unused);
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
    cmd->add_option("-o,--output", o.output, "Output image: .exr (linear) or .png (tone-mapped)");
    cmd->add_option("--aov", o.aov, "final (direct + indirect), direct, indirect, mask (1 on geometry), shadow (the first shadowed light's "
                   "visibility at the opaque surface, as render's), hair (fraction of paths stopping at a strand)");
    cmd->add_option("--exposure", o.exposure, "PNG only: linear multiplier before tone mapping")
        ->check(finiteRange(1e-6, 1e6));
    return cmd;
}

int runReferenceCommand(const ReferenceCliOptions& o, bool dryRun) {
    const std::string ext = fileExtension(o.output);
    if (ext != ".exr" && ext != ".png")
        throw std::invalid_argument(fmt::format("-o {}: the output must end in .exr or .png", o.output));
    checkWritable(o.output, "-o");
    const ReferenceAov aov = parseReferenceAov(o.aov);
    PreparedFrame f = prepareReferenceFrame(o);
    if (dryRun) return 0;
    const ReferenceImage img = renderReference(f.scene, f.camera, o.settings);
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
    cmd->add_option("--mask", o.mask, "EXR or PNG of the same size: only its non-zero pixels are compared");
    cmd->add_option("-o,--output", o.heatMap, "Heat map of |luminance(A) - luminance(B)| (PNG)");
    cmd->add_option("--heat-max", o.heatMax, "Error at the top of the heat map (default: 99th percentile)")
        ->check(finiteRange(0.0, 1e30));
    cmd->add_flag("--json", o.json, "Print the metrics as JSON");
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
    const std::vector<uint8_t> mask = o.mask.empty() ? std::vector<uint8_t>{} : loadMask(o.mask, a.width, a.height);
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
