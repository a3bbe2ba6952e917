#include "app/cli_app.h"

#include <algorithm>
#include <cstdio>

#include <fmt/format.h>

#include "app/device_budget.h"
#include "app/dsm_cli.h"
#include "app/option_checks.h"
#include "io/image_io.h"
#include "render/renderer.h"

namespace penumbra {
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
    fmt::print("penumbra: rendered '{}' ({} triangles, {}{}) on {} at {}x{} -> {}\n", scene.name,
               scene.triangleCount(),
               scene.strands.empty() ? "" : fmt::format("{} hair strands, ", scene.strands.size()),
               plural(scene.lights.size(), "light"), ctx.info().name, settings.width, settings.height, o.output);
    fmt::print("GPU time per pass{}:\n",
               o.frames > 1 ? fmt::format(" (median of {} frames after 1 warm-up)", o.frames - 1) : "");
    printTimings(timings);
    if (renderer.rsmGather() && settings.rsm.mode == RsmMode::Interpolated)
        fmt::print("  rsm fallback: {:.2f}% of pixels gathered in full\n",
                   100.0 * renderer.rsmGather()->fallbackFraction());
    if (o.printPasses) fmt::print("passes:\n{}", renderer.describePasses());
    reportDsm(renderer, false);
    const Bounds& b = scene.bounds;
    const Camera& c = f.camera;
    fmt::print("scene bounds ({:.3g}, {:.3g}, {:.3g}) .. ({:.3g}, {:.3g}, {:.3g}); camera eye ({:.3g}, {:.3g}, {:.3g})\n",
               b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z, c.eye.x, c.eye.y, c.eye.z);
}

int runRender(const RenderCliOptions& o, const vk::ContextOptions& vkOptions, RenderSettings settings, bool dryRun) {
    const std::string ext = fileExtension(o.output);
    if (ext != ".png" && ext != ".exr")
        throw std::invalid_argument(fmt::format("-o {}: the output must end in .png or .exr", o.output));
    checkWritable(o.output, "-o");
    if (dryRun) return prepareFrame(o.frame, settings), 0;
    DeviceFrame device(o.frame, settings, vkOptions);
    const PreparedFrame& f = device.frame;
    Renderer renderer(device.ctx, f.scene, settings);
    for (const std::string& w : renderer.warnings()) fmt::print(stderr, "penumbra: warning: {}\n", w);
    std::vector<std::vector<vk::ScopeTiming>> timings;
    for (int frame = 0; frame < o.frames; ++frame) {
        renderer.render(f.camera);
        timings.push_back(renderer.timings());
    }
    if (ext == ".png") writePng(o.output, settings.width, settings.height, renderer.readLdr());
    else writeExr(o.output, settings.width, settings.height, renderer.readHdr());
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

// --validate and --device on the app and on every subcommand (bound to the same settings), so that
// each subcommand's --help lists them and they may stand before or after the subcommand.
void addGlobalOptions(CLI::App& cmd, vk::ContextOptions& vkOptions, bool& dryRun) {
    cmd.add_flag("--validate", vkOptions.validate, "Enable the Khronos validation layer; any message fails the run");
    cmd.add_option("--device", vkOptions.device, "Device index or name substring (default: best GPU, else lavapipe)");
    cmd.add_flag("--dry-run", dryRun, "Check options, paths and the scene, then stop before any GPU work")
        ->envname("PENUMBRA_DRY_RUN")
        ->group("");  // hidden: for tests and scripts
}

}  // namespace

Cli::Cli(const std::string& commandLine) {
    app.option_defaults()->always_capture_default();
    app.require_subcommand(1);
    app.fallthrough();  // global options may follow the subcommand
    addGlobalOptions(app, vk, dryRun);

    renderCmd = app.add_subcommand("render", "Render a scene headless to PNG (tone-mapped) or EXR (linear)");
    renderCmd->add_option("-o,--output", render.output, "Output image (.png or .exr)");
    addFrameOptions(*renderCmd, render.frame, renderSettings);
    renderCmd->add_option("--frames", render.frames, "Frames to render; timings are the median after the first")
        ->check(CLI::Range(1, 100000));
    renderCmd->add_flag("--print-passes", render.printPasses, "Print the frame's passes with their inputs and outputs");
    renderCmd->add_flag("-q,--quiet", render.quiet, "Print nothing but warnings and errors");
    benchCmd = addBenchCommand(app, bench, benchSettings);
    bench.command = commandLine;
    infoCmd = app.add_subcommand("info", "List Vulkan devices and the features penumbra needs");
    referenceCmd = addReferenceCommand(app, reference);
    compareCmd = addCompareCommand(app, compare);
    evalCmd = addEvalCommand(app, eval);
    eval.command = commandLine;
    for (CLI::App* sub : app.get_subcommands({})) addGlobalOptions(*sub, vk, dryRun);
    requireFiniteNumbers(app);
}

std::string Cli::unknownCommand(const std::vector<std::string>& args) const {
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--device") {
            ++i;  // its value
            continue;
        }
        if (!a.empty() && a[0] == '-') {
            if (a == "-h" || a == "--help" || a == "--help-all") return "";
            continue;
        }
        if (std::find(names.begin(), names.end(), a) != names.end()) return "";
        return fmt::format("unknown command '{}' (one of: {})", a, fmt::join(names, ", "));
    }
    return fmt::format("no command given (one of: {})", fmt::join(names, ", "));
}

int Cli::run() {
    if (*infoCmd) return runInfo(vk);
    if (*benchCmd) return runBench(bench, vk, benchSettings, dryRun);
    if (*referenceCmd) return runReferenceCommand(reference, dryRun);
    if (*compareCmd) return runCompareCommand(compare, dryRun);
    if (*evalCmd) return runEvalCommand(eval, vk, dryRun);
    return runRender(render, vk, renderSettings, dryRun);
}

}  // namespace penumbra
