// penumbra command line: `render` (headless, PNG/EXR) and `info` (devices and required features).
#include <cstdio>
#include <iostream>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli_parse.h"
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
    std::string aov = "direct";
    bool printPasses = false;
    bool quiet = false;
};

void printTimings(const Renderer& r) {
    double total = 0.0;
    for (const vk::ScopeTiming& t : r.timings()) {
        fmt::print("  {:<22} {:8.3f} ms\n", t.name, t.ms);
        total += t.ms;
    }
    fmt::print("  {:<22} {:8.3f} ms\n", "total", total);
}

int runRender(const RenderOptions& o, const vk::ContextOptions& vkOptions, RenderSettings settings) {
    const std::string ext = fileExtension(o.output);
    if (ext != ".png" && ext != ".exr")
        throw std::invalid_argument(fmt::format("-o {}: the output must end in .png or .exr", o.output));
    settings.aov = parseAov(o.aov);
    Camera camera;
    std::vector<Light> lights;
    for (const std::string& l : o.lights) lights.push_back(parseLight(l));
    if (!o.camera.empty()) camera = parseCamera(o.camera);

    Scene scene = loadScene(o.scene);
    if (!lights.empty()) scene.lights = lights;
    addDefaultsIfMissing(scene);
    if (o.camera.empty()) {
        if (o.cameraIndex < 0 || o.cameraIndex >= int(scene.cameras.size()))
            throw std::invalid_argument(fmt::format("--camera-index {}: the scene has {} camera(s)", o.cameraIndex,
                                                    scene.cameras.size()));
        camera = scene.cameras[o.cameraIndex];
    }

    vk::Context ctx(vkOptions);
    Renderer renderer(ctx, scene, settings);
    for (const std::string& w : renderer.warnings()) fmt::print(stderr, "penumbra: warning: {}\n", w);
    renderer.render(camera);
    if (ext == ".png") writePng(o.output, settings.width, settings.height, renderer.readLdr());
    else writeExr(o.output, settings.width, settings.height, renderer.readHdr());
    if (!o.quiet) {
        fmt::print("penumbra: rendered '{}' ({} triangles, {} lights) on {} at {}x{} -> {}\n", scene.name,
                   scene.triangleCount(), scene.lights.size(), ctx.info().name, settings.width, settings.height,
                   o.output);
        fmt::print("GPU time per pass:\n");
        printTimings(renderer);
        if (o.printPasses) fmt::print("passes:\n{}", renderer.describePasses());
        const Bounds& b = scene.bounds;
        fmt::print("scene bounds ({:.3g}, {:.3g}, {:.3g}) .. ({:.3g}, {:.3g}, {:.3g}); camera eye ({:.3g}, {:.3g}, {:.3g})\n",
                   b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z, camera.eye.x, camera.eye.y, camera.eye.z);
    }
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
    render->add_option("--aov", ro.aov, "Output: direct, albedo, normal, depth, shadow");
    render->add_option("--exposure", rs.exposure, "Linear exposure multiplier before tone mapping")
        ->check(CLI::Range(1e-6, 1e6));
    render->add_option("--shadow-res", rs.shadow.resolution, "Shadow map resolution")->check(CLI::Range(16, 16384));
    render->add_option("--shadow-bias-constant", rs.shadow.depthBiasConstant, "Rasterizer constant depth bias")
        ->check(CLI::Range(0.0, 1e6));
    render->add_option("--shadow-bias-slope", rs.shadow.depthBiasSlope, "Rasterizer slope-scaled depth bias")
        ->check(CLI::Range(0.0, 100.0));
    render->add_option("--shadow-normal-offset", rs.shadow.normalOffset, "Receiver normal offset in shadow texels")
        ->check(CLI::Range(0.0, 100.0));
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
