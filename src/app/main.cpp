// penumbra command line: `render` (headless, PNG/EXR) and `info` (devices and required features).
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli_parse.h"
#include "app/dsm_cli.h"
#include "app/shadow_cli.h"
#include "io/image_io.h"
#include "render/renderer.h"

using namespace penumbra;

namespace {

struct RenderOptions {
    std::string scene = "cornell";
    std::string output = "penumbra.png";
    std::string camera;
    int cameraIndex = 0;
    std::vector<std::string> lights;
    std::vector<std::string> lightFilters;  // --light-shadow N=MODE
    std::string aov = "final";
    bool printPasses = false;
    int frames = 1;
    bool quiet = false;
    BuiltinOptions builtin;  // --strands
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

void addLpvOptions(CLI::App& cmd, LpvSettings& lpv) {
    cmd.add_option("--lpv-res", lpv.resolution, "LPV cells per side (default 32)")->check(CLI::Range(4, 256));
    cmd.add_option("--lpv-iterations", lpv.iterations, "LPV propagation steps (default 8)")->check(CLI::Range(1, 256));
    cmd.add_option("--lpv-cascades", lpv.cascades, "LPV cascades 1-4 (default: 1 for small scenes, 3 for large)")
        ->check(CLI::Range(1, 4));
    cmd.add_option("--lpv-rsm-res", lpv.rsmResolution, "RSM resolution for LPV injection (default 2048)")
        ->check(CLI::Range(16, 8192));
    cmd.add_option("--lpv-vpl-res", lpv.vplResolution, "Down-sampled VPLs per side (default 512)")
        ->check(CLI::Range(1, 8192));
    cmd.add_option("--lpv-occlusion", lpv.occlusion, "Geometry-volume occlusion on/off (default on)");
    cmd.add_option("--lpv-camera-geometry", lpv.cameraGeometry, "Inject camera G-buffer occluders (default on)");
    cmd.add_option("--lpv-slice-axis", lpv.sliceAxis, "Axis of the lpv-slice/gv-slice AOV: 0=x 1=y 2=z")
        ->check(CLI::Range(0, 2));
    cmd.add_option("--lpv-slice", lpv.sliceIndex, "Cell index of the lpv-slice/gv-slice AOV (default 16)");
}

void addGiOptions(CLI::App& cmd, RenderSettings& rs) {
    const std::map<std::string, GiMode> gi{{"none", GiMode::None}, {"rsm", GiMode::Rsm}, {"lpv", GiMode::Lpv}};
    const std::map<std::string, RsmMode> modes{
        {"interpolated", RsmMode::Interpolated}, {"full", RsmMode::Full}, {"all-texels", RsmMode::AllTexels}};
    const std::map<std::string, RsmWeights> weights{{"unbiased", RsmWeights::Unbiased}, {"paper", RsmWeights::Paper}};
    cmd.add_option("--gi", rs.gi, "Indirect light: none, rsm, lpv")->transform(CLI::CheckedTransformer(gi));
    cmd.add_option("--rsm-res", rs.rsm.resolution, "RSM resolution per light (default 512)")
        ->check(CLI::Range(8, 8192));
    cmd.add_option("--rsm-samples", rs.rsm.samples, "RSM gather samples per pixel (default 400)")
        ->check(CLI::Range(1, 16384));
    cmd.add_option("--rsm-radius", rs.rsm.radius, "RSM sampling radius r_max in RSM uv units (default 0.25)")
        ->check(CLI::Range(1e-4, 2.0));
    cmd.add_option("--rsm-seed", rs.rsm.seed, "Seed of the RSM sample pattern");
    cmd.add_option("--rsm-mode", rs.rsm.mode, "interpolated (default), full, all-texels (exact; --rsm-res <= 64)")
        ->transform(CLI::CheckedTransformer(modes));
    cmd.add_option("--rsm-weights", rs.rsm.weights, "Sample weights: unbiased (default) or paper (xi1^2)")
        ->transform(CLI::CheckedTransformer(weights));
    cmd.add_option("--rsm-lowres", rs.rsm.lowResFactor, "Low-resolution gather factor (default 4)")
        ->check(CLI::Range(1, 32));
    addLpvOptions(cmd, rs.lpv);
}

int runRender(const RenderOptions& o, const vk::ContextOptions& vkOptions, RenderSettings settings) {
    const std::string ext = fileExtension(o.output);
    if (ext != ".png" && ext != ".exr")
        throw std::invalid_argument(fmt::format("-o {}: the output must end in .png or .exr", o.output));
    settings.aov = parseAov(o.aov);
    finishDsmSettings(settings);
    if (settings.gi == GiMode::Lpv && settings.lpv.rsmResolution % settings.lpv.vplResolution)
        throw std::invalid_argument("--lpv-rsm-res must be a multiple of --lpv-vpl-res");
    if ((settings.aov == Aov::LpvSlice || settings.aov == Aov::GvSlice) && settings.gi != GiMode::Lpv)
        throw std::invalid_argument("--aov lpv-slice/gv-slice need --gi lpv");
    if (settings.gi == GiMode::Rsm && settings.rsm.mode == RsmMode::AllTexels && settings.rsm.resolution > 64)
        throw std::invalid_argument("--rsm-mode all-texels gathers every texel at every pixel: use --rsm-res <= 64");
    Camera camera;
    std::vector<Light> lights;
    for (const std::string& l : o.lights) lights.push_back(parseLight(l));
    if (!o.camera.empty()) camera = parseCamera(o.camera);

    Scene scene = loadScene(o.scene, o.builtin);
    if (!lights.empty()) scene.lights = lights;
    addDefaultsIfMissing(scene);
    applyLightFilters(o.lightFilters, scene.lights);
    if (o.camera.empty()) {
        if (o.cameraIndex < 0 || o.cameraIndex >= int(scene.cameras.size()))
            throw std::invalid_argument(fmt::format("--camera-index {}: the scene has {} camera(s)", o.cameraIndex,
                                                    scene.cameras.size()));
        camera = scene.cameras[o.cameraIndex];
    }

    vk::Context ctx(vkOptions);
    Renderer renderer(ctx, scene, settings);
    for (const std::string& w : renderer.warnings()) fmt::print(stderr, "penumbra: warning: {}\n", w);
    std::vector<std::vector<vk::ScopeTiming>> timings;
    for (int f = 0; f < o.frames; ++f) {
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
    render->add_option("scene", ro.scene, "glTF file (.gltf/.glb) or built-in scene: " +
                                              fmt::format("{}", fmt::join(builtinSceneNames(), ", ")));
    render->add_option("-o,--output", ro.output, "Output image (.png or .exr)");
    render->add_option("--width", rs.width, "Image width")->check(CLI::Range(1, 16384));
    render->add_option("--height", rs.height, "Image height")->check(CLI::Range(1, 16384));
    render->add_option("--camera", ro.camera, "Camera override: ex,ey,ez,tx,ty,tz,ux,uy,uz,fovy_deg");
    render->add_option("--camera-index", ro.cameraIndex, "Which of the scene's cameras to use");
    render->add_option("--light", ro.lights, "Replace the scene's lights (repeatable): see README");
    render->add_option("--aov", ro.aov,
                       "Output: final (default), direct, indirect, albedo, normal, depth, shadow, cascade, ...");
    addGiOptions(*render, rs);
    render->add_option("--exposure", rs.exposure, "Linear exposure multiplier before tone mapping")
        ->check(CLI::Range(1e-6, 1e6));
    render->add_option("--shadow-res", rs.shadow.resolution, "Shadow map resolution")->check(CLI::Range(16, 16384));
    render->add_option("--shadow-bias-constant", rs.shadow.depthBiasConstant, "Rasterizer constant depth bias")
        ->check(CLI::Range(0.0, 1e6));
    render->add_option("--shadow-bias-slope", rs.shadow.depthBiasSlope, "Rasterizer slope-scaled depth bias")
        ->check(CLI::Range(0.0, 100.0));
    render->add_option("--shadow-normal-offset", rs.shadow.normalOffset, "Receiver normal offset in shadow texels")
        ->check(CLI::Range(0.0, 100.0));
    addShadowOptions(*render, rs.shadow, ro.lightFilters, rs.dsm.enabled);
    addDsmOptions(*render, rs.dsm, ro.builtin);
    render->add_option("--frames", ro.frames, "Frames to render; timings are the median after the first")
        ->check(CLI::Range(1, 100000));
    render->add_flag("--print-passes", ro.printPasses, "Print the frame's passes with their inputs and outputs");
    render->add_flag("-q,--quiet", ro.quiet, "Print nothing but warnings and errors");
    CLI::App* info = app.add_subcommand("info", "List Vulkan devices and the features penumbra needs");

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
    try {
        if (*info) return runInfo(vkOptions);
        return runRender(ro, vkOptions, rs);
    } catch (const std::exception& e) {
        fmt::print(stderr, "penumbra: error: {}\n", e.what());
        return 1;
    }
}
