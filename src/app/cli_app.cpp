#include "app/cli_app.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <unistd.h>

#include <fmt/format.h>

#include "core/sky.h"
#include "app/dsm_cli.h"
#include "app/option_checks.h"
#include "app/option_cli.h"
#include "app/sequence.h"
#include "frame/frame_setup.h"
#include "io/image_io.h"
#include "renderer/renderer.h"
#include "rsm/rsm_technique.h"

namespace penumbra {
namespace {

OptionTable makeRenderCommandTable() {
    using R = RenderCliOptions;
    using change::kCommand;
    OptionTableBuilder<R> t("render", "Render");
    t.text("-o,--output", "output", [](R& r) -> auto& { return r.output; },
           [](const R& r) { return std::vector<std::string>{r.output}; },
           [](R& r, const std::string& v) { r.output = v; }, kCommand, "Output image (.png or .exr)")
        .placeholder = "FILE";
    t.integer(sharedFlag<BenchOptions>(benchCommandOptions(), [](BenchOptions& b) -> auto& { return b.frames; }), "frames", [](R& r) -> auto& { return r.frames; }, 1, 100000, kCommand,
              "Frames to render; timings are the median after the first");
    t.boolean("--print-passes", "print_passes", [](R& r) -> auto& { return r.printPasses; }, kCommand,
              "Print the frame's passes with their inputs and outputs")
        .bareFlag = true;
    t.boolean("-q,--quiet", "quiet", [](R& r) -> auto& { return r.quiet; }, kCommand,
              "Print nothing but warnings and errors")
        .bareFlag = true;
    t.integer("--sequence", "sequence", [](R& r) -> auto& { return r.sequence; }, 1, 1000000, kCommand,
              "Render N frames from the scene time at {render.fps} to -o out_%04d.png|exr or out.mp4 (ffmpeg)")
        .orSpecial(0, "one image");
    t.real("--fps", "fps", [](R& r) -> auto& { return r.fps; }, 1e-3, 1e4, kCommand, "Frames per second of {render.sequence}");
    return t.build();
}

OptionTable makeGlobalTable() {
    using G = GlobalOptions;
    using change::kCommand;
    OptionTableBuilder<G> t("global", "Global");
    t.boolean("--validate", "validate", [](G& g) -> auto& { return g.vk.validate; }, kCommand,
              "Enable the Khronos validation layer; any message fails the run")
        .bareFlag = true;
    t.text("--device", "device", [](G& g) -> auto& { return g.vk.device; },
           [](const G& g) { return g.vk.device.empty() ? std::vector<std::string>{} : std::vector<std::string>{g.vk.device}; },
           [](G& g, const std::string& v) { g.vk.device = v; }, kCommand,
           "Device index or name substring (default: best GPU, else lavapipe)")
        .placeholder = "INDEX|NAME";
    t.boolean("--dry-run", "dry_run", [](G& g) -> auto& { return g.dryRun; }, kCommand,
              "Check options, paths and the scene, then stop before any GPU work")
        .inGroup("")  // hidden: for tests and scripts
        .bareFlag = true;
    return t.build();
}

}  // namespace

const OptionTable& renderCommandOptions() {
    static const OptionTable table = makeRenderCommandTable();
    return table;
}

const OptionTable& globalOptions() {
    static const OptionTable table = makeGlobalTable();
    return table;
}

// On the app and on every subcommand (bound to the same settings), so that each subcommand's --help
// lists them and they may stand before or after the subcommand.
void addGlobalOptions(CLI::App& cmd, GlobalOptions& options) {
    addOptionRows(cmd, globalOptions(), &options);
    cmd.get_option(globalOptions().flagOf<GlobalOptions>([](GlobalOptions& g) -> auto& { return g.dryRun; }))
        ->envname("PENUMBRA_DRY_RUN");
}

namespace {

// Per-pass median over the rendered frames (the first frame, which warms caches, included only
// when it is the only one).
void printTimings(const std::vector<std::vector<vk::ScopeTiming>>& frames) {
    const size_t first = frames.size() > 1 ? 1 : 0;
    auto median = [&](auto value) {
        std::vector<double> v;
        for (size_t f = first; f < frames.size(); ++f) v.push_back(value(frames[f]));
        std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
        return v[v.size() / 2];
    };
    for (size_t i = 0; i < frames[0].size(); ++i)
        fmt::print("  {:<22} {:8.3f} ms\n", frames[0][i].name, median([&](const auto& t) { return t[i].ms; }));
    fmt::print("  {:<22} {:8.3f} ms\n", "total", median([](const auto& t) {
                   double sum = 0.0;
                   for (const vk::ScopeTiming& s : t) sum += s.ms;
                   return sum;
               }));
}

void printSummary(const RenderCliOptions& o, const RenderSettings& settings, const PreparedFrame& f,
                  const vk::Context& ctx, Renderer& renderer, const std::vector<std::vector<vk::ScopeTiming>>& timings) {
    const Scene& scene = f.scene;
    fmt::print("penumbra: rendered '{}' ({} triangles{}, {}{}) on {} at {}x{} -> {}\n", scene.name,
               scene.drawnTriangleCount(),
               scene.instances.size() > 1 ? fmt::format(" in {} instances of {} meshes", scene.instances.size(),
                                                         scene.meshes.size())
                                          : "",
               scene.strands.empty() ? "" : fmt::format("{} hair strands, ", scene.strands.size()),
               plural(scene.lights.size(), "light"), ctx.info().name, settings.width, settings.height, o.output);
    fmt::print("GPU time per pass{}:\n",
               o.frames > 1 ? fmt::format(" (median of {} frames after 1 warm-up)", o.frames - 1) : "");
    printTimings(timings);
    RsmTechnique* rsm = renderer.find<RsmTechnique>();
    if (rsm && rsm->gather() && settings.rsm.mode == RsmMode::Interpolated)
        fmt::print("  rsm fallback: {:.2f}% of pixels gathered in full\n", 100.0 * rsm->gather()->fallbackFraction());
    if (o.printPasses) fmt::print("passes:\n{}", renderer.describePasses());
    reportDsm(renderer, false);
    const Bounds& b = scene.bounds;
    const Camera& c = f.camera;
    fmt::print("scene bounds ({:.3g}, {:.3g}, {:.3g}) .. ({:.3g}, {:.3g}, {:.3g}); camera eye ({:.3g}, {:.3g}, {:.3g})\n",
               b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z, c.eye.x, c.eye.y, c.eye.z);
}

// The output of `render`: one image, a numbered sequence, or an mp4 through ffmpeg. Checked before any work.
struct RenderOutput {
    std::string ext;           // of each image written
    std::string pattern;       // image file name, with a %d field for a sequence
    std::string mp4;           // "" unless -o ends in .mp4
    std::string ffmpeg;
    std::filesystem::path tmp;  // the mp4's frames

    explicit RenderOutput(const RenderCliOptions& o) : ext(fileExtension(o.output)), pattern(o.output) {
        if (ext == ".mp4") {
            if (o.sequence < 1)
                throw std::invalid_argument(fmt::format(
                    "-o {}: an mp4 needs {} N", o.output,
                    renderCommandOptions().flagOf<RenderCliOptions>([](RenderCliOptions& r) -> auto& { return r.sequence; })));
            ffmpeg = findFfmpeg();
            if (ffmpeg.empty())
                throw std::invalid_argument(fmt::format(
                    "-o {}: encoding an mp4 needs the ffmpeg program, which is not on PATH (apt-get install ffmpeg, "
                    "or write PNG frames with -o out_%04d.png)", o.output));
            checkWritable(o.output, "-o");
            mp4 = o.output, ext = ".png";
            return;
        }
        if (ext != ".png" && ext != ".exr")
            throw std::invalid_argument(fmt::format("-o {}: the output must end in .png, .exr or .mp4", o.output));
        if (o.sequence > 0) checkSequencePattern(o.output);
        checkWritable(o.sequence > 0 ? sequenceFrameName(o.output, 0) : o.output, "-o");
    }
    std::string frameName(int index) {
        if (mp4.empty()) return sequenceFrameName(pattern, index);
        if (tmp.empty()) {
            tmp = std::filesystem::temp_directory_path() / fmt::format("penumbra-mp4-{}", ::getpid());
            std::filesystem::create_directories(tmp);
            pattern = (tmp / "frame_%05d.png").string();
        }
        return sequenceFrameName(pattern, index);
    }
    ~RenderOutput() {
        std::error_code ec;
        if (!tmp.empty()) std::filesystem::remove_all(tmp, ec);
    }
};

void writeImage(Renderer& renderer, const RenderSettings& settings, const std::string& ext, const std::string& path) {
    if (ext == ".png") writePng(path, settings.width, settings.height, renderer.readLdr());
    else writeExr(path, settings.width, settings.height, renderer.readHdr());
}

// A sequence of N frames: frame i at time t + i / fps, with a progress bar on a terminal.
void renderSequence(const RenderCliOptions& o, const RenderSettings& settings, Renderer& renderer,
                    const SceneMotion& motion, RenderOutput& out) {
    const bool progress = !o.quiet && isatty(fileno(stderr));
    for (int i = 0; i < o.sequence; ++i) {
        renderer.render(frameInputs(motion, o.frame.time + i / o.fps));
        writeImage(renderer, settings, out.ext, out.frameName(i));
        if (progress) {
            const int filled = (i + 1) * 30 / o.sequence;
            fmt::print(stderr, "\rrender: [{:<30}] {}/{}", std::string(size_t(filled), '#'), i + 1, o.sequence);
            std::fflush(stderr);
        }
    }
    if (progress) fmt::print(stderr, "\n");
    if (!out.mp4.empty()) encodeMp4(out.ffmpeg, out.pattern, o.fps, out.mp4);
    if (!o.quiet)
        fmt::print("penumbra: {} frames of '{}' from t = {} s at {} fps -> {}\n", o.sequence, renderer.scene().name,
                   o.frame.time, o.fps, out.mp4.empty() ? o.output : out.mp4);
}

int runRender(const RenderCliOptions& o, const vk::ContextOptions& vkOptions, RenderSettings settings, bool dryRun) {
    RenderOutput out(o);
    if (dryRun) return prepareFrame(o.frame, settings), 0;
    OptionsDeviceFrame device(o.frame, settings, vkOptions);
    const PreparedFrame& f = device.frame;
    const SceneMotion& motion = frameMotion(o.frame, device);
    resolveAutoSky(settings.lighting.sky, f.scene.lights);
    Renderer renderer(device.ctx, f.scene, settings);
    renderer.setPassScopes(true);  // the summary's per-pass table
    for (const std::string& w : renderer.warnings()) printWarning(w);
    if (o.sequence > 0) {
        renderSequence(o, settings, renderer, motion, out);
        device.checkValidation();
        return 0;
    }
    FrameInputs inputs = frameInputs(motion, o.frame.time);
    // One frame interval earlier is the previous frame: the velocity AOV shows the motion over it.
    FrameInputs before = frameInputs(motion, o.frame.time - 1.0 / o.fps);
    inputs.previous = FrameInputs::Previous{std::move(before.camera), std::move(before.instances)};
    std::vector<std::vector<vk::ScopeTiming>> timings;
    for (int frame = 0; frame < o.frames; ++frame) {
        renderer.render(inputs);
        timings.push_back(renderer.timings());
    }
    writeImage(renderer, settings, out.ext, o.output);
    if (!o.quiet) printSummary(o, settings, f, device.ctx, renderer, timings);
    else reportDsm(renderer, true);  // the overflow warning only
    device.checkValidation();
    return 0;
}

int runInfo(const vk::ContextOptions& vkOptions) {
    for (const vk::DeviceInfo& d : vk::Context::enumerate(vkOptions)) {
        fmt::print("device {}: {} ({}, Vulkan {}.{}.{}, driver {})\n", d.index, d.name, d.type,
                   VK_API_VERSION_MAJOR(d.apiVersion), VK_API_VERSION_MINOR(d.apiVersion),
                   VK_API_VERSION_PATCH(d.apiVersion), d.driver);
        fmt::print("  {}\n", d.missing.empty() ? "usable: has every feature penumbra needs"
                                               : fmt::format("NOT usable, missing: {}", fmt::join(d.missing, ", ")));
        const vk::DeviceLimits& l = d.limits;
        fmt::print("  limits: 2D images {}, {} array layers, storage buffers {:.0f} MiB, allocations {:.0f} MiB, "
                   "memory {:.0f} MiB, work groups {}x{}x{}\n",
                   l.imageDimension2D, l.imageArrayLayers, l.storageBufferRange / 1048576.0,
                   l.allocationSize / 1048576.0, l.deviceMemory / 1048576.0, l.workGroupCount[0],
                   l.workGroupCount[1], l.workGroupCount[2]);
    }
    return 0;
}

}  // namespace

Cli::Cli(const std::string& commandLine) {
    app.option_defaults()->always_capture_default();
    app.require_subcommand(1);
    app.fallthrough();  // global options may follow the subcommand
    addGlobalOptions(app, global);

    renderCmd = app.add_subcommand("render", "Render a scene headless to PNG (tone-mapped) or EXR (linear)");
    addFrameOptions(*renderCmd, render.frame, renderSettings);
    addOptionRows(*renderCmd, renderCommandOptions(), &render);
    benchCmd = addBenchCommand(app, bench, benchSettings);
    bench.command = commandLine;
    infoCmd = app.add_subcommand("info", "List Vulkan devices and the features penumbra needs");
    referenceCmd = addReferenceCommand(app, reference);
    compareCmd = addCompareCommand(app, compare);
    evalCmd = addEvalCommand(app, eval);
    eval.command = commandLine;
    stabilityCmd = addStabilityCommand(app, stability, stabilitySettings);
    stability.command = commandLine;
    helpCmd = addHelpCommand(app, help);
    for (CLI::App* sub : app.get_subcommands({})) addGlobalOptions(*sub, global);
    requireFiniteNumbers(app);
}

std::string Cli::unknownCommand(const std::vector<std::string>& args) const {
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == globalOptions().flagOf<GlobalOptions>([](GlobalOptions& g) -> auto& { return g.vk.device; })) {
            ++i;  // its value
            continue;
        }
        if (!a.empty() && a[0] == '-') {
            if (app.get_help_ptr()->check_name(a) || (app.get_help_all_ptr() && app.get_help_all_ptr()->check_name(a)))
                return "";
            continue;
        }
        if (std::find(names.begin(), names.end(), a) != names.end()) return "";
        return fmt::format("unknown command '{}' (one of: {})", a, fmt::join(names, ", "));
    }
    return fmt::format("no command given (one of: {})", fmt::join(names, ", "));
}

int Cli::run() {
    if (*helpCmd) return fmt::print("{}", helpText(help, app)), 0;
    if (*infoCmd) return runInfo(vk);
    if (*benchCmd) return runBench(bench, vk, benchSettings, dryRun);
    if (*referenceCmd) return runReferenceCommand(reference, dryRun);
    if (*compareCmd) return runCompareCommand(compare, dryRun);
    if (*evalCmd) return runEvalCommand(eval, vk, dryRun);
    if (*stabilityCmd) return runStability(stability, vk, stabilitySettings, dryRun);
    return runRender(render, vk, renderSettings, dryRun);
}

}  // namespace penumbra
