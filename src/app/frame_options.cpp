#include "app/frame_options.h"

#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "app/cli_parse.h"
#include "app/option_checks.h"
#include "app/shadow_cli.h"
#include "core/texture_upload.h"

namespace penumbra {
namespace {

void addLpvOptions(CLI::App& cmd, LpvSettings& lpv) {
    cmd.add_option("--lpv-res", lpv.resolution, "LPV cells per side")->check(CLI::Range(4, 256));
    cmd.add_option("--lpv-iterations", lpv.iterations, "LPV propagation steps")->check(CLI::Range(1, 256));
    cmd.add_option("--lpv-cascades", lpv.cascades, "LPV cascades 1-4 (0: 1 for small scenes, 3 for large)")
        ->check(CLI::Range(0, 4));
    cmd.add_option("--lpv-rsm-res", lpv.rsmResolution, "RSM resolution for LPV injection")
        ->check(CLI::Range(16, 8192));
    cmd.add_option("--lpv-vpl-res", lpv.vplResolution, "Down-sampled VPLs per side (divides --lpv-rsm-res)")
        ->check(CLI::Range(1, 8192));
    cmd.add_option("--lpv-occlusion", lpv.occlusion, "Geometry-volume occlusion on/off");
    cmd.add_option("--lpv-camera-geometry", lpv.cameraGeometry, "Inject camera G-buffer occluders on/off");
    cmd.add_option("--lpv-geometry", lpv.geometry,
                   "What blocks propagation: surfels (geometry volume) or voxels (the occupancy volume, --rsm-voxel-res)")
        ->transform(CLI::CheckedTransformer(std::map<std::string, LpvGeometry>{{"surfels", LpvGeometry::Surfels},
                                                                            {"voxels", LpvGeometry::Voxels}}));
    cmd.add_option("--lpv-slice-axis", lpv.sliceAxis, "Axis of the lpv-slice/gv-slice AOV: 0=x 1=y 2=z")
        ->check(CLI::Range(0, 2));
    cmd.add_option("--lpv-slice", lpv.sliceIndex, "Cell index of the lpv-slice/gv-slice AOV (< --lpv-res)")
        ->check(CLI::Range(0, 255));
}

void addGiOptions(CLI::App& cmd, RenderSettings& rs) {
    addChoice<GiMode>(cmd, "--gi", rs.gi, {{"none", GiMode::None}, {"rsm", GiMode::Rsm}, {"lpv", GiMode::Lpv}},
                      "Indirect light (one diffuse bounce)");
    cmd.add_option("--rsm-res", rs.rsm.resolution, "RSM resolution per light")->check(CLI::Range(8, 8192));
    cmd.add_option("--rsm-samples", rs.rsm.samples, "RSM gather samples per pixel")->check(CLI::Range(1, 16384));
    cmd.add_option("--rsm-radius", rs.rsm.radius, "RSM sampling radius r_max in RSM uv units")
        ->check(finiteRange(1e-4, 2.0));
    cmd.add_option("--rsm-seed", rs.rsm.seed, "Seed of the RSM sample pattern");
    addChoice<RsmMode>(cmd, "--rsm-mode", rs.rsm.mode,
                       {{"interpolated", RsmMode::Interpolated}, {"full", RsmMode::Full},
                        {"all-texels", RsmMode::AllTexels}},
                       "RSM gather: interpolated low-resolution, full, or all-texels (exact; --rsm-res <= 64)");
    addChoice<RsmWeights>(cmd, "--rsm-weights", rs.rsm.weights,
                          {{"unbiased", RsmWeights::Unbiased}, {"paper", RsmWeights::Paper}},
                          "RSM sample weights: unbiased, or the paper's xi1^2");
    cmd.add_option("--rsm-lowres", rs.rsm.lowResFactor, "Low-resolution gather factor")->check(CLI::Range(1, 32));
    cmd.add_option("--gi-temporal", rs.giTemporal,
                   "Accumulate the indirect light over frames, reprojected (on/off; less flicker, more lag)");
    cmd.add_option("--gi-temporal-alpha", rs.giTemporalAlpha, "Temporal accumulation: the new frame's weight")
        ->check(finiteRange(1e-3, 1.0));
    addChoice<bool>(cmd, "--rsm-vpls", rs.rsm.bilinearVpls, {{"nearest", false}, {"bilinear", true}},
                    "A gather sample's VPL: the texel it falls in, or the four around it weighted bilinearly "
                    "(4x the cost; steadier under moving lights)");
    addChoice<RsmVisibility>(cmd, "--rsm-visibility", rs.rsm.visibility,
                             {{"none", RsmVisibility::None}, {"depth", RsmVisibility::Depth},
                              {"views", RsmVisibility::Views}, {"voxels", RsmVisibility::Voxels}},
                             "Whether a VPL sees its receiver: not tested, far samples against the RSM's depth, "
                             "every sample against the RSM's and the camera's depth, or every sample through the "
                             "scene's occupancy volume");
    cmd.add_option("--rsm-visibility-points", rs.rsm.visibilityPoints,
                   "Views visibility: points of a VPL-receiver segment tested against the two depth maps")
        ->check(CLI::Range(1, 16));
    cmd.add_option("--rsm-voxel-res", rs.rsm.voxelResolution,
                   "Occupancy volume (--rsm-visibility voxels): voxels along the scene's longest side")
        ->check(CLI::Range(8, 1024));
    addChoice<RsmRadii>(cmd, "--rsm-radii", rs.rsm.radii, {{"fixed", RsmRadii::Fixed}, {"shifted", RsmRadii::Shifted}},
                        "The sample pattern's radii: the same for every receiver, or shifted per receiver "
                        "(unbiased; always with --rsm-visibility voxels)");
    addChoice<RsmFar>(cmd, "--rsm-far", rs.rsm.far, {{"disc", RsmFar::Disc}, {"flux", RsmFar::Flux}},
                      "The far half of the RSM samples: a disc over the whole map, or texels drawn by their "
                      "flux (combined with the r_max disc's by the balance heuristic)");
    cmd.add_option("--rsm-visibility-rays", rs.rsm.visibilityRays,
                   "Voxel visibility: samples a pixel tests through the occupancy volume (the visible share "
                   "of their light scales all samples' light)")
        ->check(CLI::Range(1, 16384));
    cmd.add_flag("--rsm-per-cascade", rs.rsm.perCascade,
                 "A sun's RSM per cascade (the seed's way) instead of from its widest cascade only");
    addLpvOptions(cmd, rs.lpv);
}

// Consistency of the options with each other (each one alone is checked by its validator).
void checkCombinations(const RenderSettings& s) {
    if (s.gi == GiMode::Lpv && s.lpv.rsmResolution % s.lpv.vplResolution)
        throw std::invalid_argument(fmt::format("--lpv-rsm-res {} must be a multiple of --lpv-vpl-res {}",
                                                s.lpv.rsmResolution, s.lpv.vplResolution));
    if ((s.aov == Aov::LpvSlice || s.aov == Aov::GvSlice) && s.gi != GiMode::Lpv)
        throw std::invalid_argument("--aov lpv-slice/gv-slice need --gi lpv");
    if ((s.aov == Aov::LpvSlice || s.aov == Aov::GvSlice) && s.lpv.sliceIndex >= s.lpv.resolution)
        throw std::invalid_argument(fmt::format("--lpv-slice {} is outside the {} cells of --lpv-res",
                                                s.lpv.sliceIndex, s.lpv.resolution));
    // Indirect light without GI is black everywhere: an error rather than a silent black image.
    if (s.aov == Aov::Indirect && s.gi == GiMode::None)
        throw std::invalid_argument("--aov indirect shows indirect light only: it needs --gi rsm or --gi lpv");
    const bool rsmView = s.aov == Aov::RsmDepth || s.aov == Aov::RsmNormal || s.aov == Aov::RsmFlux;
    if (rsmView && s.gi == GiMode::None)
        throw std::invalid_argument("--aov rsm-depth/rsm-normal/rsm-flux need --gi rsm or --gi lpv");
    if (s.gi == GiMode::Rsm && s.rsm.mode == RsmMode::AllTexels && s.rsm.resolution > 64)
        throw std::invalid_argument("--rsm-mode all-texels gathers every texel at every pixel: use --rsm-res <= 64");
    if (!std::isfinite(s.exposure) || s.exposure <= 0.0f)
        throw std::invalid_argument("--exposure must be a positive finite number");
    validate(s.shadow);
}

}  // namespace

void addFrameOptions(CLI::App& cmd, FrameOptions& o, RenderSettings& rs) {
    // The defaults show what penumbra is for: one bounce of indirect light (RSM, interpolated) and
    // soft shadows (PCF); README "CLI" gives the reasons and the cost.
    rs.gi = GiMode::Rsm;
    rs.shadow.filter = ShadowFilter::Pcf;
    cmd.add_option("scene", o.scene, "glTF file (.gltf/.glb) or built-in scene: " +
                                              fmt::format("{}", fmt::join(builtinSceneNames(), ", ")));
    cmd.add_option("--width", rs.width, "Image width")->check(CLI::Range(1, 16384));
    cmd.add_option("--height", rs.height, "Image height")->check(CLI::Range(1, 16384));
    cmd.add_option("--camera", o.camera, "Camera override: ex,ey,ez,tx,ty,tz,ux,uy,uz,fovy_deg");
    cmd.add_option("--camera-index", o.cameraIndex, "Which of the scene's (perspective) cameras to use")
        ->check(CLI::NonNegativeNumber);
    cmd.add_option("--light", o.lights, "Replace the scene's lights (repeatable): see README");
    cmd.add_option("--aov", o.aov, "Output: " + fmt::format("{}", fmt::join(aovNames(), ", ")));
    cmd.add_option("--aov-layer", rs.aovLayer, "Layer shown by the rsm-depth/normal/flux and shadow-map AOVs")
        ->check(CLI::Range(0, 4096));
    addChoice<CameraPath>(cmd, "--camera-path", rs.cameraPath,
                          {{"visibility", CameraPath::Visibility}, {"gbuffer", CameraPath::Gbuffer}},
                          "Camera G-buffer: visibility buffer (depth + triangle ID raster, albedo and normal "
                          "resolved in compute) or the classic raster G-buffer");
    addGiOptions(cmd, rs);
    cmd.add_option("--exposure", rs.exposure, "Linear exposure multiplier before tone mapping")
        ->check(finiteRange(1e-6, 1e6));
    addShadowOptions(cmd, rs.shadow, o.lightFilters, rs.dsm);
    addDsmOptions(cmd, rs.dsm, o.builtin);
    cmd.add_option("--translucency", rs.translucency,
                   "Hair and BLEND surfaces composited in depth order on/off (off: drawn opaque)");
    addMotionOptions(cmd, o);
}

void addMotionOptions(CLI::App& cmd, FrameOptions& o) {
    cmd.add_option("--time", o.time, "Scene time in seconds (animation, motion paths)")->check(finiteRange(-1e6, 1e6));
    cmd.add_option("--animation", o.animation.animation, "Play only glTF animation N (default: all)")
        ->check(CLI::Range(0, 1 << 20));
    cmd.add_flag("--clamp", o.animation.clamp, "Hold the last key of animations instead of looping");
    cmd.add_option("--sun-path", o.motion.sun, "Sun motion: AZ0,EL0,AZ1,EL1,SECONDS (degrees; every directional light)");
    cmd.add_option("--light-path", o.motion.lights, "Light N's position keys: N:T,X,Y,Z;T,X,Y,Z;... (repeatable)");
    cmd.add_option("--camera-keys", o.motion.camera, "Camera motion keys: T,EX,EY,EZ,TX,TY,TZ;... (eye and target)");
    cmd.add_flag_function("--no-motion", [&o](int64_t) { o.motion.builtinDefault = false; },
                          "No default motion of the built-in scenes");
}

SceneMotion frameMotion(const FrameOptions& o, const PreparedFrame& f) {
    SceneMotion motion(f.scene, f.camera, f.scene.lights, o.motion, o.animation);
    if (o.time != 0.0 && !motion.moves())
        fmt::print(stderr, "penumbra: warning: --time {}: nothing in '{}' moves (no animation or motion path)\n",
                   o.time, f.scene.name);
    return motion;
}

FrameInputs frameInputs(const SceneMotion& motion, double t) {
    ScenePose pose = motion.at(t);
    return {std::move(pose.camera), std::move(pose.lights), std::move(pose.instances)};
}

void checkFrameSettings(const FrameOptions& o, RenderSettings& settings) {
    settings.aov = parseAov(o.aov);
    finishDsmSettings(settings);
    checkCombinations(settings);
    if (settings.aov == Aov::Velocity && settings.cameraPath == CameraPath::Gbuffer)
        fmt::print(stderr, "penumbra: warning: --aov velocity with --camera-path gbuffer shows camera motion only "
                           "(moving objects need the visibility path's triangle IDs)\n");
    if (settings.gi == GiMode::Rsm && settings.rsm.bilinearVpls && settings.rsm.far == RsmFar::Flux &&
        settings.rsm.weights == RsmWeights::Unbiased)
        fmt::print(stderr, "penumbra: warning: --rsm-vpls bilinear applies to the r_max disc's samples only: the flux "
                           "draws stay texels (--rsm-far disc for a gather continuous in the light's motion)\n");
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
        throw std::invalid_argument(fmt::format("--camera-index {}: the scene has {}", o.cameraIndex,
                                                plural(scene.cameras.size(), "camera")));
    return scene.cameras[o.cameraIndex];
}

PreparedFrame prepareFrame(const FrameOptions& o, RenderSettings& settings) {
    checkFrameSettings(o, settings);
    // Malformed --light / --camera values fail before a slow scene load.
    for (const std::string& l : o.lights) parseLight(l);
    if (!o.camera.empty()) parseCamera(o.camera);
    checkMotionPaths(o.motion);
    PreparedFrame f;
    f.scene = loadScene(o.scene, o.builtin);
    for (const std::string& w : f.scene.warnings) fmt::print(stderr, "penumbra: warning: {}\n", w);
    if (const std::string w = planTextureTable(f.scene.textures).warning(); !w.empty())
        fmt::print(stderr, "penumbra: warning: {}\n", w);
    f.scene.lights = frameLights(o, f.scene);
    f.camera = frameCamera(o, f.scene);
    SceneMotion(f.scene, f.camera, f.scene.lights, o.motion, o.animation);  // --animation N exists, paths fit
    return f;
}

}  // namespace penumbra
