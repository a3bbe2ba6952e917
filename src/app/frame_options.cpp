#include "app/frame_options.h"

#include <map>

#include <fmt/format.h>

#include "app/cli_parse.h"
#include "app/shadow_cli.h"

namespace penumbra {
namespace {

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
    cmd.add_flag("--rsm-per-cascade", rs.rsm.perCascade,
                 "A sun's RSM per cascade (the seed's way) instead of from its widest cascade only");
    addLpvOptions(cmd, rs.lpv);
}

}  // namespace

void addFrameOptions(CLI::App& cmd, FrameOptions& o, RenderSettings& rs) {
    cmd.add_option("scene", o.scene, "glTF file (.gltf/.glb) or built-in scene: " +
                                              fmt::format("{}", fmt::join(builtinSceneNames(), ", ")));
    cmd.add_option("--width", rs.width, "Image width")->check(CLI::Range(1, 16384));
    cmd.add_option("--height", rs.height, "Image height")->check(CLI::Range(1, 16384));
    cmd.add_option("--camera", o.camera, "Camera override: ex,ey,ez,tx,ty,tz,ux,uy,uz,fovy_deg");
    cmd.add_option("--camera-index", o.cameraIndex, "Which of the scene's cameras to use");
    cmd.add_option("--light", o.lights, "Replace the scene's lights (repeatable): see README");
    cmd.add_option("--aov", o.aov,
                       "Output: final (default), direct, indirect, albedo, normal, depth, shadow, cascade, ...");
    cmd.add_option("--aov-layer", rs.aovLayer, "Layer shown by the rsm-depth/normal/flux and shadow-map AOVs (default 0)")
        ->check(CLI::Range(0, 4096));
    addGiOptions(cmd, rs);
    cmd.add_option("--exposure", rs.exposure, "Linear exposure multiplier before tone mapping")
        ->check(CLI::Range(1e-6, 1e6));
    addShadowOptions(cmd, rs.shadow, o.lightFilters, rs.dsm.enabled);
    addDsmOptions(cmd, rs.dsm, o.builtin);
}

void checkFrameSettings(const FrameOptions& o, RenderSettings& settings) {
    settings.aov = parseAov(o.aov);
    finishDsmSettings(settings);
    if (settings.gi == GiMode::Lpv && settings.lpv.rsmResolution % settings.lpv.vplResolution)
        throw std::invalid_argument("--lpv-rsm-res must be a multiple of --lpv-vpl-res");
    if ((settings.aov == Aov::LpvSlice || settings.aov == Aov::GvSlice) && settings.gi != GiMode::Lpv)
        throw std::invalid_argument("--aov lpv-slice/gv-slice need --gi lpv");
    const bool rsmView = settings.aov == Aov::RsmDepth || settings.aov == Aov::RsmNormal || settings.aov == Aov::RsmFlux;
    if (rsmView && settings.gi == GiMode::None)
        throw std::invalid_argument("--aov rsm-depth/rsm-normal/rsm-flux need --gi rsm or --gi lpv");
    if (settings.gi == GiMode::Rsm && settings.rsm.mode == RsmMode::AllTexels && settings.rsm.resolution > 64)
        throw std::invalid_argument("--rsm-mode all-texels gathers every texel at every pixel: use --rsm-res <= 64");
}

std::vector<Light> frameLights(const FrameOptions& o, const Scene& loaded) {
    std::vector<Light> lights;
    for (const std::string& l : o.lights) lights.push_back(parseLight(l));
    if (lights.empty()) lights = loaded.lights;  // loadScene added the default sun where there is none
    applyLightFilters(o.lightFilters, lights);
    return lights;
}

Camera frameCamera(const FrameOptions& o, const Scene& scene) {
    if (!o.camera.empty()) return parseCamera(o.camera);
    if (o.cameraIndex < 0 || o.cameraIndex >= int(scene.cameras.size()))
        throw std::invalid_argument(
            fmt::format("--camera-index {}: the scene has {} camera(s)", o.cameraIndex, scene.cameras.size()));
    return scene.cameras[o.cameraIndex];
}

PreparedFrame prepareFrame(const FrameOptions& o, RenderSettings& settings) {
    checkFrameSettings(o, settings);
    // Malformed --light / --camera values fail before a slow scene load.
    for (const std::string& l : o.lights) parseLight(l);
    if (!o.camera.empty()) parseCamera(o.camera);
    PreparedFrame f;
    f.scene = loadScene(o.scene, o.builtin);
    f.scene.lights = frameLights(o, f.scene);
    f.camera = frameCamera(o, f.scene);
    return f;
}

}  // namespace penumbra
