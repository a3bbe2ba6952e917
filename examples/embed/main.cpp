// Renders one frame of a glTF file (or a built-in scene) with PCF shadows and RSM global
// illumination through penumbra's public API, and writes it as a PNG.
//   embed SCENE OUT.png [WIDTH HEIGHT]
#include <cstdio>
#include <exception>
#include <string>

#include <penumbra/penumbra.h>

namespace api = penumbra::api;

namespace {

api::SceneData loadScene(const std::string& name) {
    const bool file = name.ends_with(".gltf") || name.ends_with(".glb");
    return file ? api::SceneData::fromGltf(name) : api::SceneData::builtin(name);
}

int run(int argc, char** argv) {
    if (argc != 3 && argc != 5) {
        std::fprintf(stderr, "usage: embed SCENE OUT.png [WIDTH HEIGHT]\n");
        return 2;
    }
    const std::string output = argv[2];

    api::Settings settings;
    if (argc == 5) {
        settings.width = uint32_t(std::stoul(argv[3]));
        settings.height = uint32_t(std::stoul(argv[4]));
    }
    settings.shadow.filter = api::ShadowFilter::Pcf;
    settings.gi = api::GiMode::Rsm;
    settings.rsm.samples = 300;  // the technique's own settings struct, as installed

    api::Device device;  // the best device; api::ExternalDevice hands in an engine's own
    const api::SceneData scene = loadScene(argv[1]);
    for (const std::string& w : scene.warnings()) std::fprintf(stderr, "embed: warning: %s\n", w.c_str());

    api::Renderer renderer(device, scene, settings);
    renderer.setPassTimings(true);
    renderer.render(scene.frame(0.0));  // the scene's first camera and its lights at t = 0

    api::writePng(output, settings.width, settings.height, renderer.readRgba8());
    const api::Timings timings = renderer.timings();
    std::printf("embed: '%s' (%zu triangles) on %s -> %s\n", scene.name().c_str(), scene.triangleCount(),
                device.name().c_str(), output.c_str());
    for (const api::PassTiming& pass : timings.passes) std::printf("  %-22s %8.3f ms\n", pass.name.c_str(), pass.ms);
    std::printf("  %-22s %8.3f ms\n", "frame", timings.gpuMs);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "embed: error: %s\n", e.what());
        return 1;
    }
}
