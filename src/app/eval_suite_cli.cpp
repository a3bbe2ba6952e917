// `penumbra eval --suite` (eval_suite_cli.h): per scene its references (two seeds), the sun-only case
// and, for the outdoor scenes, the sky case; the tables, the JSON and the figures.
#include "app/eval_suite_cli.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "app/option_cli.h"
#include "core/gpu_scene.h"
#include "io/file_write.h"
#include "io/image_io.h"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

// Pixels whose surface faces down (normal y < -0.9): cornell's ceiling, from the renderer's normal AOV.
std::vector<uint8_t> downFacingPixels(vk::Context& ctx, const PreparedFrame& f, RenderSettings s) {
    GpuScene gpuScene(ctx, f.scene);
    s.aov = Aov::Normal;
    s.gi = GiMode::None;
    Renderer r(ctx, gpuScene, s, 1);
    r.render(f.camera);
    const std::vector<float> normal = r.readHdr();
    std::vector<uint8_t> out(size_t(s.width) * s.height);
    for (size_t i = 0; i < out.size(); ++i) out[i] = normal[i * 4 + 1] < -0.9f;
    return out;
}

// The command's options for one suite scene: its scene, camera, lights, size and paths.
EvalCliOptions suiteSceneOptions(const EvalCliOptions& suite, const SuiteScene& sc) {
    EvalCliOptions o = suite;
    o.reference.frame.scene = sc.scene;
    // Through the input rows, which parse what they are given (prepareFrame takes the parsed values).
    const OptionTable& inputs = frameInputOptions();
    const OptionRow* cameraRow = inputs.find(cameraFlag());
    const OptionRow* lightRow = inputs.find(inputs.flagOf<FrameOptions>([](FrameOptions& i) -> auto& { return i.lights; }));
    if (!sc.camera.empty()) cameraRow->set(&o.reference.frame, sc.camera);
    if (!sc.lights.empty()) lightRow->clear(&o.reference.frame);
    for (const std::string& light : sc.lights) lightRow->set(&o.reference.frame, light);
    o.reference.settings.width = sc.width;
    o.reference.settings.height = sc.height;
    o.reference.settings.spp = sc.spp;
    return o;
}

// The reference of `f` for `seed`, cached under o.referenceDir/<cacheName>-seed<N>.
GroundTruth cachedTruth(const EvalCliOptions& o, const PreparedFrame& f, const std::string& cacheName, uint64_t seed) {
    EvalCliOptions so = o;
    so.reference.settings.seed = seed;
    if (!o.referenceDir.empty())
        so.referenceDir = (fs::path(o.referenceDir) / fmt::format("{}-seed{}", cacheName, seed)).string();
    return groundTruth(so, f);
}

auto progressPrinter(bool progressLine, const std::string& name) {
    return [progressLine, name](size_t i, size_t n, const std::string& t) {
        if (progressLine) fmt::print(stderr, "\reval {}: {} {}/{} {:<40}", suiteFlag(), name, i + 1, n, t), std::fflush(stderr);
    };
}

void writeFigure(const EvalCliOptions& o, const std::string& name, const std::vector<EvalRow>& rows,
                 const GroundTruth& truth) {
    double heat = 0.0;
    uint32_t w = 0, h = 0;
    const std::vector<uint8_t> fig = evalFigure(rows, truth, autoExposure(truth.final, truth.mask),
                                                autoExposure(truth.indirect, truth.mask), o.figureCellWidth, heat, w, h);
    writePng((fs::path(o.images) / (name + ".png")).string(), w, h, fig);
}

// One suite scene's sun-only case: RSM and LPV at their defaults against its reference, the figure.
SuiteResult runSunCase(const EvalCliOptions& o, const SuiteScene& sc, const PreparedFrame& f, const GroundTruth& truth,
                       const GroundTruth& second, vk::Context& ctx, bool progressLine) {
    SuiteResult r{sc.name, sc.width, sc.height, sc.spp, 0.0, {}, -1.0, -1.0};
    r.noiseL1 = compareImages(second.indirect, truth.indirect, truth.mask).relL1;
    RenderSettings base;
    base.width = sc.width;
    base.height = sc.height;
    // --frames still frames (32): the figure of what the GI history converges to, as the docs state it.
    r.rows = runEval(ctx, f.scene, f.camera, suiteVariants(base), truth, o.frames,
                     progressPrinter(progressLine, sc.name));
    if (sc.name == "cornell") {
        const std::vector<uint8_t> ceiling = downFacingPixels(ctx, f, base);
        r.ceilingRsm = regionRatio(r.rows[0].indirectImage, truth.indirect, ceiling);
        r.ceilingLpv = regionRatio(r.rows[1].indirectImage, truth.indirect, ceiling);
    }
    if (!o.images.empty()) writeFigure(o, sc.name, r.rows, truth);
    return r;
}

// One suite scene's sky case (eval/sky_suite.h): the sky-alone references (two seeds, cached under
// <name>-sky-seed<N>) beside the sun-only ones, the renders of the sky alone and of sun and sky.
SkySuiteResult runSkyCase(const EvalCliOptions& o, const SuiteScene& sc, const PreparedFrame& f,
                          const GroundTruth& sun, const GroundTruth& sunSecond, vk::Context& ctx, bool progressLine) {
    const SkySettings sky = suiteSky();
    EvalCliOptions skyOptions = o;
    skyOptions.reference.settings.sky = skyOnlySky(sky, f.scene.lights);
    PreparedFrame skyFrame = f;
    skyFrame.scene.lights = skyOnlyLights(f.scene.lights);
    const uint64_t seed = o.reference.settings.seed;
    const SkyCaseTruths truths{sun, cachedTruth(skyOptions, skyFrame, sc.name + "-sky", seed), sunSecond,
                               cachedTruth(skyOptions, skyFrame, sc.name + "-sky", seed + 1)};
    RenderSettings base;
    base.width = sc.width;
    base.height = sc.height;
    SkySuiteResult r = runSkyCase(ctx, f.scene, f.camera, sky, truths, base, o.frames,
                                  progressPrinter(progressLine, sc.name + " sky"));
    r.scene = sc.name;
    r.spp = sc.spp;
    if (!o.images.empty()) {
        std::vector<EvalRow> skyOnly;
        for (const SkyTermRow& row : r.rows) skyOnly.push_back(row.skyOnly);
        writeFigure(o, sc.name + "-sky", skyOnly, truths.sky);
    }
    return r;
}

bool runsSun(const EvalCliOptions& o) { return o.suiteCases != SuiteCases::Sky; }
bool runsSky(const EvalCliOptions& o, const SuiteScene& sc) {
    return o.suiteCases != SuiteCases::Sun && hasSkyCase(sc.name);
}

void printSunTable(const std::vector<SuiteResult>& results, const EvalCliOptions& o, const vk::Context& ctx) {
    fmt::print("penumbra eval {} on {}: indirect light against the one-bounce path tracer, over the pixels with "
               "geometry after {} still frames; RSM and LPV at their defaults, hard shadows\n{}",
               suiteFlag(), ctx.info().name, o.frames, formatSuiteTable(results));
    for (const SuiteResult& r : results)
        if (r.ceilingLpv >= 0.0)
            fmt::print("{} ceiling, mean indirect / reference's: RSM {:.2f}, LPV {:.2f}\n", r.scene, r.ceilingRsm,
                       r.ceilingLpv);
    fmt::print("ref noise: indirect relative L1 between the references of two seeds. GPU cost: `penumbra bench` "
               "(docs/benchmarks.md), not eval's timing.\n");
    if (!o.images.empty()) fmt::print("figures {}/<scene>.png: columns reference, RSM, LPV; rows final, indirect, "
                                      "indirect error (auto-exposed)\n", o.images);
}

void printSkyTable(const std::vector<SkySuiteResult>& results, const EvalCliOptions& o, const vk::Context& ctx) {
    fmt::print("penumbra eval {} sky cases on {}: the view's lights and the analytic sky, relative L1 over the pixels "
               "with geometry after {} still frames; sky direct and sky bounce from the sky alone (lights off, the "
               "same sky), final from sun and sky against the sum of the sun-only and sky-alone references\n{}",
               suiteFlag(), ctx.info().name, o.frames, formatSkySuiteTable(results));
    fmt::print("ref noise d/b/f: relative L1 between the references of two seeds of the sky's direct light, its bounce "
               "and the final image. The renderer's sky direct is final - indirect of two renders.\n");
    if (!o.images.empty()) fmt::print("figures {}/<scene>-sky.png: the sky alone; columns reference, RSM, LPV; rows "
                                      "final, indirect (the sky's bounce), indirect error (auto-exposed)\n", o.images);
}

}  // namespace

SuiteRun runSuiteCases(const EvalCliOptions& o, const std::vector<SuiteScene>& scenes, vk::Context& ctx,
                       bool progressLine) {
    SuiteRun run;
    for (const SuiteScene& sc : scenes) {
        if (!runsSun(o) && !runsSky(o, sc)) continue;
        const EvalCliOptions so = suiteSceneOptions(o, sc);
        const PreparedFrame f = prepareReferenceFrame(so.reference);
        const uint64_t seed = so.reference.settings.seed;
        const GroundTruth truth = cachedTruth(so, f, sc.name, seed), second = cachedTruth(so, f, sc.name, seed + 1);
        if (runsSun(o)) run.sun.push_back(runSunCase(so, sc, f, truth, second, ctx, progressLine));
        if (runsSky(o, sc)) run.sky.push_back(runSkyCase(so, sc, f, truth, second, ctx, progressLine));
    }
    return run;
}

int runSuite(const EvalCliOptions& o, const vk::ContextOptions& vkOptions, bool dryRun) {
    const std::vector<SuiteScene> scenes = suiteScenes(o.assets, o.suiteScenes);
    if (std::none_of(scenes.begin(), scenes.end(), [&](const SuiteScene& sc) { return runsSun(o) || runsSky(o, sc); }))
        throw std::invalid_argument(fmt::format(
            "{} sky: none of the scenes given has a sky case ({}); give one of them to {}",
            evalFlag([](EvalCliOptions& e) -> auto& { return e.suiteCases; }), fmt::join(kSkySuiteScenes, ", "),
            evalFlag([](EvalCliOptions& e) -> auto& { return e.suiteScenes; })));
    for (const SuiteScene& sc : scenes)  // every file is checked before any work
        if (sc.scene.find('/') != std::string::npos && !fs::is_regular_file(sc.scene))
            throw std::invalid_argument(fmt::format("{} {}: no {} (suite scene '{}')", evalFlag([](EvalCliOptions& e) -> auto& { return e.assets; }), o.assets, sc.scene, sc.name));
    if (dryRun) return 0;
    const bool progressLine = o.reference.settings.progress && isatty(STDERR_FILENO);
    std::error_code ec;
    if (!o.images.empty()) fs::create_directories(o.images, ec);
    vk::Context ctx(vkOptions);
    const SuiteRun run = runSuiteCases(o, scenes, ctx, progressLine);
    if (progressLine) fmt::print(stderr, "\r{:80}\r", "");
    if (!run.sun.empty()) printSunTable(run.sun, o, ctx);
    if (!run.sky.empty()) printSkyTable(run.sky, o, ctx);
    if (!o.json.empty()) {
        nlohmann::json j{{"command", o.command}, {"device", ctx.info().name}, {"scenes", suiteJson(run.sun)}};
        if (!run.sky.empty()) j["sky_scenes"] = skySuiteJson(run.sky);
        writeTextFile(o.json, j.dump(2));
    }
    if (ctx.validationMessages() > 0)
        throw std::runtime_error(fmt::format("{} validation message(s) reported", ctx.validationMessages()));
    return 0;
}

}  // namespace penumbra
