// penumbra command line: `render` (headless, PNG/EXR), `view` (interactive), `bench` (per-pass GPU
// timings), `info`, and the ground truth: `reference` (CPU path tracer), `compare` (image metrics), `eval` (techniques vs reference).
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/bench.h"
#include "app/dsm_cli.h"
#include "app/frame_options.h"
#include "app/ground_truth_cli.h"
#include "io/image_io.h"
#include "render/renderer.h"
#include "view/view_command.h"

using namespace penumbra;

namespace {

struct RenderOptions {
    FrameOptions frame;
    std::string output = "penumbra.png";
    bool printPasses = false;
    int frames = 1;
    bool quiet = false;
};

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

int runRender(const RenderOptions& o, const vk::ContextOptions& vkOptions, RenderSettings settings) {
    const std::string ext = fileExtension(o.output);
    if (ext != ".png" && ext != ".exr")
        throw std::invalid_argument(fmt::format("-o {}: the output must end in .png or .exr", o.output));
    PreparedFrame f = prepareFrame(o.frame, settings);
    const Scene& scene = f.scene;
    const Camera& camera = f.camera;

    vk::Context ctx(vkOptions);
    Renderer renderer(ctx, scene, settings);
    for (const std::string& w : renderer.warnings()) fmt::print(stderr, "penumbra: warning: {}\n", w);
    std::vector<std::vector<vk::ScopeTiming>> timings;
    for (int frame = 0; frame < o.frames; ++frame) {
        renderer.render(camera);
        timings.push_back(renderer.timings());
    }
    if (ext == ".png") writePng(o.output, settings.width, settings.height, renderer.readLdr());
    else writeExr(o.output, settings.width, settings.height, renderer.readHdr());
    if (!o.quiet) {
        fmt::print("penumbra: rendered '{}' ({} triangles, {}{} lights) on {} at {}x{} -> {}\n", scene.name,
                   scene.triangleCount(),
                   scene.strands.empty() ? "" : fmt::format("{} hair strands, ", scene.strands.size()),
                   scene.lights.size(), ctx.info().name, settings.width, settings.height, o.output);
        fmt::print("GPU time per pass{}:\n",
                   o.frames > 1 ? fmt::format(" (median of {} frames after 1 warm-up)", o.frames - 1) : "");
        printTimings(timings);
        if (renderer.rsmGather() && settings.rsm.mode == RsmMode::Interpolated)
            fmt::print("  rsm fallback: {:.2f}% of pixels gathered in full\n",
                       100.0 * renderer.rsmGather()->fallbackFraction());
        if (o.printPasses) fmt::print("passes:\n{}", renderer.describePasses());
        reportDsm(renderer, false);
        const Bounds& b = scene.bounds;
        fmt::print("scene bounds ({:.3g}, {:.3g}, {:.3g}) .. ({:.3g}, {:.3g}, {:.3g}); camera eye ({:.3g}, {:.3g}, {:.3g})\n",
                   b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z, camera.eye.x, camera.eye.y, camera.eye.z);
    }
    if (o.quiet) reportDsm(renderer, true);  // the overflow warning only
    if (ctx.validationMessages() > 0)
        throw std::runtime_error(fmt::format("{} validation message(s) reported", ctx.validationMessages()));
    return 0;
}

int runInfo(const vk::ContextOptions& vkOptions) {
    for (const vk::DeviceInfo& d : vk::Context::enumerate(vkOptions)) {
        fmt::print("device {}: {} ({}, Vulkan {}.{}.{}, driver {})\n", d.index, d.name, d.type,
                   VK_API_VERSION_MAJOR(d.apiVersion), VK_API_VERSION_MINOR(d.apiVersion),
                   VK_API_VERSION_PATCH(d.apiVersion), d.driver);
        fmt::print("  {}\n", d.missing.empty() ? "usable: has every feature penumbra needs"
                                               : fmt::format("NOT usable, missing: {}", fmt::join(d.missing, ", ")));
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"penumbra: real-time shadows and diffuse global illumination (Vulkan 1.3)"};
    app.require_subcommand(1);
    app.fallthrough();  // global options may follow the subcommand
    vk::ContextOptions vkOptions;
    app.add_flag("--validate", vkOptions.validate, "Enable the Khronos validation layer; any message fails the run");
    app.add_option("--device", vkOptions.device, "Device index or name substring (default: best GPU, else lavapipe)");

    RenderOptions ro;
    RenderSettings rs;
    CLI::App* render = app.add_subcommand("render", "Render a scene headless to PNG (tone-mapped) or EXR (linear)");
    render->add_option("-o,--output", ro.output, "Output image (.png or .exr)");
    addFrameOptions(*render, ro.frame, rs);
    render->add_option("--frames", ro.frames, "Frames to render; timings are the median after the first")
        ->check(CLI::Range(1, 100000));
    render->add_flag("--print-passes", ro.printPasses, "Print the frame's passes with their inputs and outputs");
    render->add_flag("-q,--quiet", ro.quiet, "Print nothing but warnings and errors");
    BenchOptions bo;
    RenderSettings bs;
    CLI::App* bench = addBenchCommand(app, bo, bs);
    for (int i = 0; i < argc; ++i) bo.command += (i ? " " : "") + std::string(argv[i]);
    view::ViewCommand viewCommand;
    CLI::App* viewer = view::addViewCommand(app, viewCommand);
    CLI::App* info = app.add_subcommand("info", "List Vulkan devices and the features penumbra needs");
    ReferenceCliOptions refOptions;
    CLI::App* reference = addReferenceCommand(app, refOptions);
    CompareCliOptions compareOptions;
    CLI::App* compare = addCompareCommand(app, compareOptions);
    EvalCliOptions evalOptions;
    CLI::App* eval = addEvalCommand(app, evalOptions);
    evalOptions.command = bo.command;

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::string msg = e.what();
        if (msg.empty()) msg = e.get_name();
        fmt::print(stderr, "penumbra: error: {} (see --help)\n", msg);
        return 2;
    }
    vkOptions.syncValidation = vkOptions.validate;  // --validate checks synchronization too
    try {
        if (*info) return runInfo(vkOptions);
        if (*bench) return runBench(bo, vkOptions, bs);
        if (*reference) return runReferenceCommand(refOptions);
        if (*compare) return runCompareCommand(compareOptions);
        if (*eval) return runEvalCommand(evalOptions, vkOptions);
        if (*viewer) return view::runViewCommand(viewCommand, vkOptions);
        return runRender(ro, vkOptions, rs);
    } catch (const std::exception& e) {
        fmt::print(stderr, "penumbra: error: {}\n", e.what());
        return 1;
    }
}
