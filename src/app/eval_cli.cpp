// `penumbra eval` (ground_truth_cli.h): the reference (rendered, or read from its cache directory),
// every technique in one Vulkan context, the table, the JSON and the side-by-side figure.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/eval_suite_cli.h"
#include "app/bench.h"
#include "app/option_checks.h"
#include "app/option_cli.h"
#include "io/file_write.h"
#include "eval/eval.h"
#include "eval/hair_eval.h"
#include "eval/suite.h"
#include "core/gpu_scene.h"
#include "io/image_io.h"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

// The smallest image eval measures: the SSIM window (eval/compare.cpp) fits inside it.
constexpr uint32_t kMinEvalSize = 16;

// Everything the reference image depends on: a cache entry is reused only when all of it matches. The
// sky is named only when there is one, so that the keys of sun-only references stay as they were.
nlohmann::json referenceKey(const EvalCliOptions& o, const PreparedFrame& f) {
    const Camera& c = f.camera;
    const ReferenceSettings& s = o.reference.settings;
    nlohmann::json lights = nlohmann::json::array();
    for (const Light& l : f.scene.lights)
        lights.push_back({int(l.type), l.position.x, l.position.y, l.position.z, l.direction.x, l.direction.y,
                          l.direction.z, l.color.x, l.color.y, l.color.z, l.intensity, l.range, l.innerConeAngle,
                          l.outerConeAngle, l.castsShadow});
    nlohmann::json key{{"scene", o.reference.frame.scene}, {"triangles", f.scene.triangleCount()},
                       {"strands", f.scene.strands.size()}, {"strand_points", f.scene.strandPoints.size()},
                       {"camera", {c.eye.x, c.eye.y, c.eye.z, c.target.x, c.target.y, c.target.z, c.up.x, c.up.y,
                                   c.up.z, c.fovy, c.znear, c.zfar}},
                       {"lights", lights}, {"width", s.width}, {"height", s.height}, {"spp", s.spp},
                       {"bounces", s.bounces}, {"seed", s.seed}, {"antialias", s.antialias}};
    if (s.sky.kind != SkyKind::None && s.sky.kind != SkyKind::Auto)
        key["sky"] = {skyText(s.sky), s.sky.scale, s.sky.rotationDegrees};
    return key;
}

GroundTruth fromImages(ImageF direct, ImageF indirect, const ImageF& mask, ImageF shadow, ImageF hair,
                       const nlohmann::json& noise) {
    GroundTruth t{std::move(direct), std::move(indirect), {}, {}, noise.value("final", 0.0),
                  noise.value("indirect", 0.0), std::move(shadow), std::move(hair), noise.value("hair", 0.0)};
    t.final = t.direct;
    for (size_t k = 0; k < t.final.rgba.size(); ++k) t.final.rgba[k] += t.indirect.rgba[k];
    t.mask.resize(size_t(mask.width) * mask.height);
    for (size_t i = 0; i < t.mask.size(); ++i) t.mask[i] = mask.rgba[i * 4] != 0.0f;
    return t;
}

template <class Access>
const std::string& sceneFlag(Access access) {
    return referenceSceneOptions().flagOf<ReferenceCliOptions>(access);
}
const std::string& hairFlag() { return evalFlag([](EvalCliOptions& e) -> auto& { return e.hair; }); }
const std::string& sppFlag() { return sceneFlag([](ReferenceCliOptions& r) -> auto& { return r.settings.spp; }); }

}  // namespace

const std::string& suiteFlag() { return evalFlag([](EvalCliOptions& e) -> auto& { return e.suite; }); }
const std::string& cameraFlag() {
    return frameInputOptions().flagOf<FrameOptions>([](FrameOptions& f) -> auto& { return f.camera; });
}

// The reference from the cache directory when its key matches, else rendered (and stored there).
// DIR/reference.json: {"key": what it depends on, "noise": its relative standard errors}.
GroundTruth groundTruth(const EvalCliOptions& o, const PreparedFrame& f) {
    const nlohmann::json key = referenceKey(o, f);
    const fs::path dir = o.referenceDir;
    if (!o.referenceDir.empty() && fs::exists(dir / "reference.json")) {
        nlohmann::json stored = nlohmann::json::parse(std::ifstream(dir / "reference.json"), nullptr, false);
        if (!stored.is_discarded() && stored.is_object() && stored.value("key", nlohmann::json()) == key) {
            if (o.reference.settings.progress) fmt::print("penumbra: reference read from {}\n", o.referenceDir);
            // The key names the size: an image of another size is a damaged cache, named in the error.
            const auto cached = [&](const char* name) {
                return readExrSized((dir / name).string(), evalFlag([](EvalCliOptions& e) -> auto& { return e.referenceDir; }), o.reference.settings.width,
                                    o.reference.settings.height);
            };
            return fromImages(cached("direct.exr"), cached("indirect.exr"), cached("mask.exr"), cached("shadow.exr"),
                              cached("hair.exr"),
                              stored.value("noise", nlohmann::json::object()));
        }
    }
    const ReferenceImage img = renderReference(f.scene, f.camera, o.reference.settings);
    const uint32_t w = img.width, h = img.height;
    std::vector<uint8_t> hairPixels(img.hair.size());  // as eval --hair selects them
    for (size_t i = 0; i < hairPixels.size(); ++i) hairPixels[i] = img.hair[i] >= kHairPixelAlpha;
    const nlohmann::json noise{{"final", img.relativeNoise(ReferenceAov::Final)},
                               {"hair", img.relativeNoise(ReferenceAov::Final, hairPixels)},
                               {"indirect", img.relativeNoise(ReferenceAov::Indirect)}};
    if (o.reference.settings.progress)
        fmt::print("penumbra: reference rendered: {} paths/pixel, {} bounce(s), {:.1f} s\n", img.spp,
                   o.reference.settings.bounces, img.seconds);
    if (!o.referenceDir.empty()) {
        std::error_code ec;
        fs::create_directories(dir, ec);
        writeExr((dir / "direct.exr").string(), w, h, img.rgba(ReferenceAov::Direct));
        writeExr((dir / "indirect.exr").string(), w, h, img.rgba(ReferenceAov::Indirect));
        writeExr((dir / "mask.exr").string(), w, h, img.rgba(ReferenceAov::Mask));
        writeExr((dir / "shadow.exr").string(), w, h, img.rgba(ReferenceAov::Shadow));
        writeExr((dir / "hair.exr").string(), w, h, img.rgba(ReferenceAov::Hair));
        writeTextFile((dir / "reference.json").string(), nlohmann::json{{"key", key}, {"noise", noise}}.dump(2));
    }
    return fromImages({w, h, img.rgba(ReferenceAov::Direct)}, {w, h, img.rgba(ReferenceAov::Indirect)},
                      {w, h, img.rgba(ReferenceAov::Mask)}, {w, h, img.rgba(ReferenceAov::Shadow)},
                      {w, h, img.rgba(ReferenceAov::Hair)}, noise);
}

namespace {

using change::kCommand;

OptionRow& pathRow(OptionTableBuilder<EvalCliOptions>& t, const char* flag, const char* key,
                   std::string EvalCliOptions::*member, const char* help) {
    using E = EvalCliOptions;
    OptionRow& row = t.text(
        flag, key, [member](E& e) -> auto& { return e.*member; },
        [member](const E& e) { return (e.*member).empty() ? std::vector<std::string>{} : std::vector<std::string>{e.*member}; },
        [member](E& e, const std::string& v) { e.*member = v; }, kCommand, help);
    row.placeholder = "PATH";
    return row;
}

OptionTable makeEvalCommandTable() {
    using E = EvalCliOptions;
    OptionTableBuilder<E> t("eval", "Eval");
    pathRow(t, "--reference", "reference", &E::referenceDir,
            "Reference cache directory: reused when scene and settings match");
    pathRow(t, sharedFlag<BenchOptions>(benchCommandOptions(), [](BenchOptions& b) -> auto& { return b.json; }), "json",
            &E::json, "Write the table and every metric as JSON to this file");
    pathRow(t, "--images", "images", &E::images, "Directory for figure.png: reference, RSM, LPV, their error maps");
    t.integer(sharedFlag<BenchOptions>(benchCommandOptions(), [](BenchOptions& b) -> auto& { return b.frames; }),
              "frames", [](E& e) -> auto& { return e.frames; }, 1, 10000, kCommand,
              "Frames per technique, of a still view (the GI history accumulates them); GPU ms is the median "
              "after the first");
    t.real(sharedFlag<RenderSettings>(frameOptionTable(), [](RenderSettings& s) -> auto& { return s.exposure; }),
           "exposure", [](E& e) -> auto& { return e.reference.exposure; }, 1e-6, 1e6, kCommand,
           "Figure: exposure of the final images")
        .orSpecial(0, "auto");
    t.real("--indirect-exposure", "indirect_exposure", [](E& e) -> auto& { return e.indirectExposure; }, 1e-6, 1e6,
           kCommand, "Figure: exposure of the indirect images")
        .orSpecial(0, "auto");
    t.integer("--figure-width", "figure_width", [](E& e) -> auto& { return e.figureCellWidth; }, 16, 16384, kCommand,
              "Figure: largest cell width, pixels");
    t.boolean("--suite", "suite", [](E& e) -> auto& { return e.suite; }, kCommand,
              "The GI suite: cornell, street, room, Sponza, VC at fixed sizes; RSM and LPV defaults against the "
              "reference ({eval.reference}: the cache folder)")
        .bareFlag = true;
    pathRow(t, "--assets", "assets", &E::assets, "{eval.suite}: the folder holding sponza/ and VC/");
    OptionRow& scenes = t.text(
        "--scenes", "scenes", [](E& e) -> auto& { return e.suiteScenes; }, [](const E& e) { return e.suiteScenes; },
        [](E& e, const std::string& v) {
            std::stringstream list(v);
            for (std::string name; std::getline(list, name, ',');) {
                suiteScenes("", {name});  // throws for a name the suite does not have
                e.suiteScenes.push_back(name);
            }
        },
        kCommand, "{eval.suite}: only these scenes (cornell, street, room, sponza, vc)");
    scenes.repeatable = true;
    scenes.placeholder = "NAME,...";
    scenes.clear = [](void* e) { static_cast<E*>(e)->suiteScenes.clear(); };
    t.choice("--suite-cases", "suite_cases", [](E& e) -> auto& { return e.suiteCases; },
             std::vector<std::pair<std::string, SuiteCases>>{
                 {"all", SuiteCases::All}, {"sun", SuiteCases::Sun}, {"sky", SuiteCases::Sky}},
             kCommand,
             "{eval.suite}: sun (each scene with its lights, no sky), sky (street, Sponza and VC with the analytic "
             "sky: the sky's direct light, its bounce and the final image, each against the path tracer) or all");
    t.boolean("--hair", "hair", [](E& e) -> auto& { return e.hair; }, kCommand,
              "The hair evaluation: every shadow filter and deep shadow maps against the path-traced strands "
              "(anti-aliased, direct light): image and floor transmittance")
        .bareFlag = true;
    return t.build();
}

}  // namespace

const OptionTable& evalCommandOptions() {
    static const OptionTable table = makeEvalCommandTable();
    return table;
}

CLI::App* addEvalCommand(CLI::App& app, EvalCliOptions& o) {
    CLI::App* cmd = app.add_subcommand("eval", "Render every GI mode and shadow filter and measure each against the "
                                               "path-traced reference: one table");
    o.reference.settings.width = 320;
    o.reference.settings.height = 240;
    o.reference.settings.spp = 256;
    o.reference.exposure = 0.0f;  // 0: auto (the figure's exposures come from the reference)
    o.indirectExposure = 0.0f;
    addReferenceSceneOptions(*cmd, o.reference);
    addOptionRows(*cmd, evalCommandOptions(), &o);
    cmd->get_option(sceneFlag([](ReferenceCliOptions& r) -> auto& { return r.settings.bounces; }))
        ->each([&o](const std::string&) { o.bouncesGiven = true; });
    return cmd;
}

namespace {

// `eval --hair --images DIR`: DIR/hair-figure.png (eval/hair_eval.h).
void writeHairFigure(const EvalCliOptions& o, const std::vector<HairEvalRow>& rows, const HairGroundTruth& h) {
    std::error_code ec;
    fs::create_directories(o.images, ec);
    double heat = 0.0;
    uint32_t w = 0, fh = 0;
    // Not the auto exposure: the floor outside the spot's cone drags the log-average down (x100).
    const float exposure = o.reference.exposure > 0.0f ? o.reference.exposure : 1.0f;
    const std::vector<uint8_t> fig = hairEvalFigure(rows, h, exposure, o.figureCellWidth, heat, w, fh);
    const std::string path = (fs::path(o.images) / "hair-figure.png").string();
    writePng(path, w, fh, fig);
    fmt::print("figure {}: columns reference, PCF, DSM; rows final (x{:.3g}), floor transmittance T (white 1), "
               "|T - T_ref| over the measured floor pixels (black 0 .. pale yellow {:.3g}; grey: not measured)\n",
               path, exposure, heat);
}

// `eval --hair` (eval/hair_eval.h): the anti-aliased, direct-light reference of the scene and of
// the scene without its strands (cached in DIR and DIR/without-strands), then every shadow technique.
int runHairEvalCommand(const EvalCliOptions& given, const vk::ContextOptions& vkOptions, bool dryRun) {
    EvalCliOptions o = given;
    o.reference.settings.antialias = true;  // strands far thinner than a pixel: samples over its area
    o.reference.settings.bounces = 0;       // direct light: neither side has GI through hair
    const PreparedFrame f = prepareReferenceFrame(o.reference);
    if (f.scene.strands.empty())
        throw std::invalid_argument(fmt::format("{}: scene '{}' has no hair strands", hairFlag(), f.scene.name));
    if (given.bouncesGiven && given.reference.settings.bounces != 0)
        fmt::print(stderr, "penumbra: warning: {} compares direct light: {} {} ignored (0)\n", hairFlag(),
                   sceneFlag([](ReferenceCliOptions& r) -> auto& { return r.settings.bounces; }),
                   given.reference.settings.bounces);
    if (dryRun) return 0;
    const bool progressLine = o.reference.settings.progress && isatty(STDERR_FILENO);
    const GroundTruth truth = groundTruth(o, f);
    PreparedFrame bareFrame = f;
    bareFrame.scene = withoutStrands(f.scene);
    EvalCliOptions bareOptions = o;
    if (!o.referenceDir.empty()) bareOptions.referenceDir = (fs::path(o.referenceDir) / "without-strands").string();
    const GroundTruth bare = groundTruth(bareOptions, bareFrame);

    vk::Context ctx(vkOptions);
    RenderSettings base;
    base.width = o.reference.settings.width;
    base.height = o.reference.settings.height;
    const HairGroundTruth h = makeHairGroundTruth(truth.final, truth.mask, truth.hair, truth.shadow, bare.shadow,
                                                  floorPixels(ctx, f.scene, f.camera, base), truth.noiseFinal);
    auto count = [](const std::vector<uint8_t>& m) { return size_t(std::count(m.begin(), m.end(), uint8_t(1))); };
    if (count(h.hairPixels) == 0 || count(h.shadowPixels) == 0)
        throw std::runtime_error(fmt::format("{}: the camera sees {} hair pixels and {} floor pixels in the hair's "
                                             "shadow: nothing to measure (another {}?)", hairFlag(),
                                             count(h.hairPixels), count(h.shadowPixels), cameraFlag()));
    const std::vector<HairEvalRow> rows = runHairEval(
        ctx, f.scene, f.camera, hairEvalVariants(base), h, o.frames, [&](size_t i, size_t n, const std::string& name) {
            if (progressLine) fmt::print(stderr, "\reval {}: {}/{} {:<40}", hairFlag(), i + 1, n, name), std::fflush(stderr);
        });
    if (progressLine) fmt::print(stderr, "\r{:80}\r", "");
    const bool gpu = ctx.info().type != "cpu";
    double refT = 0.0;
    for (size_t i = 0; i < h.shadowPixels.size(); ++i) refT += h.shadowPixels[i] ? h.transmittance.rgba[i * 4] : 0.0;
    refT /= double(count(h.shadowPixels));
    fmt::print("penumbra eval {}: '{}' ({} strands) {}x{} on {}; reference {} anti-aliased paths/pixel, direct "
               "light (no GI on either side)\nimage L2 over the {} pixels with geometry, hair L2 over the {} where the "
               "reference's paths stop at a strand in >= {:.0f}%; floor T = shadow AOV with / without the strands over "
               "the {} floor pixels in the hair's shadow (reference mean T {:.3f}); bias = mean(T - T_ref)\n",
               hairFlag(), f.scene.name, f.scene.strands.size(), base.width, base.height, ctx.info().name, o.reference.settings.spp,
               count(h.mask), count(h.hairPixels), 100.0 * kHairPixelAlpha, count(h.shadowPixels), refT);
    fmt::print("{}", formatHairEvalTable(rows, gpu));
    for (const HairEvalRow& r : rows)
        for (const std::string& w : r.warnings) printWarning(r.variant.technique + ": " + w);
    fmt::print("reference noise (its own relative L2 error, the floor of the L2 columns): image {:.3f}, hair pixels "
               "{:.3f}\n", truth.noiseFinal, truth.noiseHair);
    if (!gpu) fmt::print("(GPU ms left out: {} is a CPU device)\n", ctx.info().name);
    if (!o.images.empty()) writeHairFigure(o, rows, h);
    if (!o.json.empty()) {
        nlohmann::json j{{"command", o.command}, {"device", ctx.info().name}, {"device_type", ctx.info().type},
                         {"scene", f.scene.name}, {"strands", f.scene.strands.size()}, {"width", base.width},
                         {"height", base.height},
                         {"reference", {{"spp", o.reference.settings.spp}, {"antialias", true}, {"bounces", 0},
                                        {"seed", o.reference.settings.seed}, {"noise_final", truth.noiseFinal},
                                        {"noise_hair_pixels", truth.noiseHair}}},
                         {"mask_pixels", count(h.mask)}, {"hair_pixels", count(h.hairPixels)},
                         {"floor_shadow_pixels", count(h.shadowPixels)}, {"reference_mean_transmittance", refT},
                         {"rows", hairEvalRowsJson(rows)}};
        writeTextFile(o.json, j.dump(2));
    }
    if (ctx.validationMessages() > 0)
        throw std::runtime_error(fmt::format("{} validation message(s) reported", ctx.validationMessages()));
    return 0;
}

// The errors eval reports are relative to the reference, and its noise floor is a variance: one path
// per pixel estimates no variance (a noise of 0), and an image smaller than the SSIM window leaves
// the windowed metrics without a window.
void checkMeasurable(const ReferenceSettings& s) {
    if (s.spp < 2)
        throw std::invalid_argument(fmt::format("eval {0} {1}: the reference's noise is estimated from the variance of "
                                                "its paths, which needs at least 2 per pixel (e.g. {0} 16)", sppFlag(), s.spp));
    if (s.width < kMinEvalSize || s.height < kMinEvalSize)
        throw std::invalid_argument(fmt::format("eval {0} {2} {1} {3}: the image must be at least {4}x{4} to measure (e.g. {0} 32 {1} 24)",
                                                sceneFlag([](ReferenceCliOptions& r) -> auto& { return r.settings.width; }),
                                                sceneFlag([](ReferenceCliOptions& r) -> auto& { return r.settings.height; }),
                                                s.width, s.height, kMinEvalSize));
}

// A reference that is black where the camera sees geometry (or, with bounces, has no indirect light
// there) leaves the relative errors infinite.
void checkReferenceSignal(const GroundTruth& truth, const ReferenceSettings& s) {
    size_t covered = 0;
    double finalSq = 0.0, indirectSq = 0.0;
    for (size_t i = 0; i < truth.mask.size(); ++i) {
        if (!truth.mask[i]) continue;
        ++covered;
        for (size_t c = i * 4; c < i * 4 + 3; ++c) {
            finalSq += double(truth.final.rgba[c]) * truth.final.rgba[c];
            indirectSq += double(truth.indirect.rgba[c]) * truth.indirect.rgba[c];
        }
    }
    const char* missing = covered == 0 || finalSq == 0.0           ? "black"
                          : s.bounces > 0 && indirectSq == 0.0 ? "without indirect light"
                                                               : nullptr;
    if (missing)
        throw std::runtime_error(fmt::format("eval: the reference ({}x{}, {} paths/pixel) is {} over the {} pixels with "
                                             "geometry: nothing to measure; give more {} or another {}",
                                             s.width, s.height, s.spp, missing, covered, sppFlag(), cameraFlag()));
}

}  // namespace

int runEvalCommand(const EvalCliOptions& o, const vk::ContextOptions& vkOptions, bool dryRun) {
    const bool verbose = o.reference.settings.progress;
    const bool progressLine = verbose && isatty(STDERR_FILENO);  // \r redraws only on a terminal, not in logs
    // Every output is checked before the reference (minutes) and the techniques run.
    if (!o.json.empty()) checkWritable(o.json, evalFlag([](EvalCliOptions& e) -> auto& { return e.json; }));
    if (!o.images.empty()) checkWritable(o.images, evalFlag([](EvalCliOptions& e) -> auto& { return e.images; }), true);
    if (!o.referenceDir.empty()) checkWritable(o.referenceDir, evalFlag([](EvalCliOptions& e) -> auto& { return e.referenceDir; }), true);
    if (o.suite && o.hair) throw std::invalid_argument(fmt::format("{} and {}: one evaluation at a time", suiteFlag(), hairFlag()));
    if (o.suite) return runSuite(o, vkOptions, dryRun);
    if (o.hair) return runHairEvalCommand(o, vkOptions, dryRun);
    checkMeasurable(o.reference.settings);
    PreparedFrame f = prepareReferenceFrame(o.reference);
    if (dryRun) return 0;
    const GroundTruth truth = groundTruth(o, f);
    checkReferenceSignal(truth, o.reference.settings);

    vk::Context ctx(vkOptions);
    RenderSettings base;
    base.width = o.reference.settings.width;
    base.height = o.reference.settings.height;
    bool sun = false;
    for (const Light& l : f.scene.lights) sun |= l.type == LightType::Directional && l.castsShadow;
    const std::vector<EvalVariant> variants = evalVariants(base, sun);
    const std::vector<EvalRow> rows =
        runEval(ctx, f.scene, f.camera, variants, truth, o.frames, [&](size_t i, size_t n, const std::string& name) {
            if (progressLine) fmt::print(stderr, "\reval: {}/{} {:<60}", i + 1, n, name), std::fflush(stderr);
        });
    if (progressLine) fmt::print(stderr, "\r{:80}\r", "");
    const bool gpu = ctx.info().type != "cpu";
    size_t covered = 0;
    for (uint8_t m : truth.mask) covered += m;
    fmt::print("penumbra eval: '{}' {}x{} on {}; reference {} paths/pixel, {} bounce(s); relative L2 errors over the "
               "{} pixels with geometry\n",
               f.scene.name, base.width, base.height, ctx.info().name, o.reference.settings.spp,
               o.reference.settings.bounces, covered);
    fmt::print("{}", formatEvalTable(rows, gpu));
    fmt::print("reference noise (its own relative L2 error, the floor of the L2 columns): total {:.3f}, indirect "
               "{:.3f}\n", truth.noiseFinal, truth.noiseIndirect);
    if (!gpu) fmt::print("(GPU ms left out: {} is a CPU device)\n", ctx.info().name);
    if (!o.images.empty()) {
        std::error_code ec;
        fs::create_directories(o.images, ec);
        double heat = 0.0;
        uint32_t w = 0, h = 0;
        const float exposure = o.reference.exposure > 0.0f ? o.reference.exposure : autoExposure(truth.final, truth.mask);
        const float indirectExposure =
            o.indirectExposure > 0.0f ? o.indirectExposure : autoExposure(truth.indirect, truth.mask);
        const std::vector<uint8_t> fig =
            evalFigure(rows, truth, exposure, indirectExposure, o.figureCellWidth, heat, w, h);
        const std::string path = (fs::path(o.images) / "figure.png").string();
        writePng(path, w, h, fig);
        fmt::print("figure {}: columns reference, RSM interpolated, LPV 32^3; rows final (x{:.3g}), indirect (x{:.3g}), "
                   "indirect error |dY| (black 0 .. pale yellow {:.4g}; the reference column shows the ramp)\n",
                   path, exposure, indirectExposure, heat);
    }
    if (!o.json.empty()) {
        nlohmann::json j{{"command", o.command},  {"device", ctx.info().name}, {"device_type", ctx.info().type},
                         {"scene", f.scene.name}, {"width", base.width},       {"height", base.height},
                         {"reference", {{"spp", o.reference.settings.spp}, {"bounces", o.reference.settings.bounces},
                                        {"seed", o.reference.settings.seed},
                                        {"noise_final", truth.noiseFinal}, {"noise_indirect", truth.noiseIndirect}}},
                         {"mask_pixels", covered}, {"rows", evalRowsJson(rows)}};
        writeTextFile(o.json, j.dump(2));
    }
    if (ctx.validationMessages() > 0)
        throw std::runtime_error(fmt::format("{} validation message(s) reported", ctx.validationMessages()));
    return 0;
}

}  // namespace penumbra
