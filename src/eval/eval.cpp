#include "eval/eval.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "renderer/render_options.h"

namespace penumbra {
namespace {

EvalVariant giVariant(const RenderSettings& base, GiMode gi, const std::string& technique,
                      const std::string& settings) {
    EvalVariant v{technique, settings, base, false};
    v.render.gi = gi;
    v.render.shadow.filter = ShadowFilter::Hard;
    return v;
}

constexpr uint32_t kGap = 4;  // white pixels between the figure's cells

// Copies `src` (w x h RGBA8) into the figure at cell (col, row) of cells w x h.
void blit(std::vector<uint8_t>& dst, uint32_t dstWidth, const std::vector<uint8_t>& src, uint32_t w, uint32_t h,
          uint32_t col, uint32_t row) {
    for (uint32_t y = 0; y < h; ++y)
        std::copy(src.begin() + size_t(y) * w * 4, src.begin() + size_t(y + 1) * w * 4,
                  dst.begin() + ((size_t(row) * (h + kGap) + y) * dstWidth + size_t(col) * (w + kGap)) * 4);
}

// Box-filters a w x h RGBA8 image down by an integer factor (the figure's cells stay small).
std::vector<uint8_t> shrink(const std::vector<uint8_t>& src, uint32_t w, uint32_t h, uint32_t factor) {
    if (factor <= 1) return src;
    const uint32_t sw = w / factor, sh = h / factor;
    std::vector<uint8_t> out(size_t(sw) * sh * 4);
    for (uint32_t y = 0; y < sh; ++y)
        for (uint32_t x = 0; x < sw; ++x)
            for (int c = 0; c < 4; ++c) {
                uint32_t sum = 0;
                for (uint32_t j = 0; j < factor; ++j)
                    for (uint32_t i = 0; i < factor; ++i)
                        sum += src[((size_t(y) * factor + j) * w + size_t(x) * factor + i) * 4 + c];
                out[(size_t(y) * sw + x) * 4 + c] = uint8_t((sum + factor * factor / 2) / (factor * factor));
            }
    return out;
}

// The heat map's colour ramp across a cell (left 0, right = the scale), for the reference column.
std::vector<uint8_t> rampCell(uint32_t w, uint32_t h) {
    ImageF zero{w, h, std::vector<float>(size_t(w) * h * 4, 0.0f)}, ramp = zero;
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) ramp.rgba[(size_t(y) * w + x) * 4 + c] = (x + 0.5f) / float(w);
    double scale = 1.0;
    return errorHeatMap(ramp, zero, {}, scale);
}

}  // namespace

std::string fmtValue(double v, const char* spec) {
    if (std::isnan(v)) return "-";
    if (std::isinf(v)) return "inf";
    return fmt::format(fmt::runtime(spec), v);
}

nlohmann::json metricsJson(const ImageMetrics& m) {
    auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
    return {{"pixels", m.pixels},         {"rmse", num(m.rmse)},         {"rel_l1", num(m.relL1)},
            {"rel_l2", num(m.relL2)},     {"mean_bias", num(m.meanBias)}, {"relative_bias", num(relativeBias(m))},
            {"max_error", num(m.maxError)}, {"ssim", num(m.ssim)},      {"ssim_range", num(m.ssimRange)}};
}

double medianOf(std::vector<double> v) {
    if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

std::vector<EvalVariant> evalVariants(const RenderSettings& base, bool sun) {
    std::vector<EvalVariant> v;
    v.push_back(giVariant(base, GiMode::None, "none", "direct light only, hard shadows"));
    EvalVariant rsmFull = giVariant(base, GiMode::Rsm, "rsm full", "");
    rsmFull.render.rsm.mode = RsmMode::Full;
    rsmFull.settings = fmt::format("{}^2, {} samples, r_max {}", rsmFull.render.rsm.resolution,
                                   rsmFull.render.rsm.samples, rsmFull.render.rsm.radius);
    v.push_back(rsmFull);
    EvalVariant rsmInterp = rsmFull;
    rsmInterp.technique = "rsm interpolated";
    rsmInterp.render.rsm.mode = RsmMode::Interpolated;
    rsmInterp.settings += fmt::format(", 1/{} res", rsmInterp.render.rsm.lowResFactor);
    rsmInterp.figure = true;
    v.push_back(rsmInterp);
    if (sun) {  // a sun's RSM follows its shadow cascades (one per receiver); one map of the whole scene instead
        EvalVariant one = rsmFull;
        one.render.shadow.cascades.count = 1;
        one.settings += ", 1 sun cascade";
        v.push_back(one);
    }
    // LPV: the default, a finer grid with more steps, and a coarse grid that carries light far.
    const std::pair<uint32_t, uint32_t> lpv[] = {{32, 8}, {64, 16}, {16, 32}};
    for (auto [res, steps] : lpv) {
        EvalVariant l = giVariant(base, GiMode::Lpv, "lpv", fmt::format("{}^3 x {} steps", res, steps));
        l.render.lpv.resolution = res;
        l.render.lpv.iterations = steps;
        l.render.lpv.sliceIndex = res / 2;
        l.figure = res == 32;
        v.push_back(l);
    }
    for (const std::string& name : shadowFilterNames()) {
        const ShadowFilter f = parseShadowFilter(name, "eval");
        if (f == ShadowFilter::Hard) continue;  // the "none" row
        EvalVariant s = giVariant(base, GiMode::None, "shadow " + name, "no GI, default filter parameters");
        s.render.shadow.filter = f;
        v.push_back(s);
    }
    return v;
}

double relativeBias(const ImageMetrics& m) {
    return m.refMean > 0.0 ? m.meanBias / m.refMean : std::numeric_limits<double>::quiet_NaN();
}

std::vector<EvalRow> runEval(vk::Context& ctx, const Scene& scene, const Camera& camera,
                             const std::vector<EvalVariant>& variants, const GroundTruth& truth, int frames,
                             const std::function<void(size_t, size_t, const std::string&)>& progress) {
    std::vector<EvalRow> rows;
    // One upload of the scene; each variant is a settings change of one renderer (frames waited for).
    GpuScene gpuScene(ctx, scene);
    // Two renderers in step, one per image: the frames of a GI history differ from one another, so the
    // final image and the indirect light come from the same frame of two identical histories.
    std::unique_ptr<Renderer> renderer, indirectRenderer;
    for (size_t i = 0; i < variants.size(); ++i) {
        const EvalVariant& v = variants[i];
        if (progress) progress(i, variants.size(), v.technique + " " + v.settings);
        RenderSettings s = v.render;
        s.aov = Aov::Final;
        RenderSettings si = s;
        si.aov = Aov::Indirect;
        if (renderer) renderer->apply(s), indirectRenderer->apply(si);
        else
            renderer = std::make_unique<Renderer>(ctx, gpuScene, s, 1),
            indirectRenderer = std::make_unique<Renderer>(ctx, gpuScene, si, 1);
        Renderer& r = *renderer;
        std::vector<double> ms;
        for (int f = 0; f < std::max(frames, 1); ++f) {
            r.render(camera);
            indirectRenderer->render(camera);
            if (f > 0 || frames <= 1) ms.push_back(r.frameTimings().gpuMs);  // the first frame warms caches
        }
        EvalRow row{v, medianOf(ms), {}, {}, {}, {}, {}};
        ImageF final{s.width, s.height, r.readHdr()};
        ImageF indirect{s.width, s.height, indirectRenderer->readHdr()};
        // direct = final - indirect: the two frames are identical but for what the lighting pass writes.
        ImageF direct = final;
        for (size_t k = 0; k < direct.rgba.size(); ++k) direct.rgba[k] -= indirect.rgba[k];
        row.direct = compareImages(direct, truth.direct, truth.mask);
        row.total = compareImages(final, truth.final, truth.mask);
        row.indirect = compareImages(indirect, truth.indirect, truth.mask);
        if (v.figure) row.final = std::move(final), row.indirectImage = std::move(indirect);
        rows.push_back(std::move(row));
    }
    return rows;
}

std::string formatEvalTable(const std::vector<EvalRow>& rows, bool gpu) {
    // Markdown, so that docs/evaluation.md can take the table as it is.
    constexpr const char* kRow = "| {:<18} | {:<46} | {:>8} | {:>9} | {:>9} | {:>10} | {:>9} | {:>11} |\n";
    std::string out = fmt::format(kRow, "technique", "settings", "GPU ms", "direct L2", "total L2", "total SSIM",
                                  "indir. L2", "indir. bias");
    out += fmt::format(kRow, std::string(18, '-'), std::string(46, '-'), "-------:", "--------:", "--------:",
                       "---------:", "--------:", "----------:");
    for (const EvalRow& r : rows)
        out += fmt::format(kRow, r.variant.technique, r.variant.settings, gpu ? fmtValue(r.frameMs) : "-",
                           fmtValue(r.direct.relL2), fmtValue(r.total.relL2), fmtValue(r.total.ssim),
                           fmtValue(r.indirect.relL2), fmtValue(relativeBias(r.indirect), "{:+.3f}"));
    return out;
}

nlohmann::json evalRowsJson(const std::vector<EvalRow>& rows) {
    nlohmann::json out = nlohmann::json::array();
    for (const EvalRow& r : rows)
        out.push_back({{"technique", r.variant.technique},
                       {"settings", r.variant.settings},
                       {"render_settings", renderSettingsJson(r.variant.render)},
                       {"frame_ms", std::isfinite(r.frameMs) ? nlohmann::json(r.frameMs) : nlohmann::json(nullptr)},
                       {"direct", metricsJson(r.direct)},
                       {"total", metricsJson(r.total)},
                       {"indirect", metricsJson(r.indirect)}});
    return out;
}

std::vector<uint8_t> evalFigure(const std::vector<EvalRow>& rows, const GroundTruth& truth, float exposure,
                                float indirectExposure, uint32_t maxCellWidth, double& heatScale, uint32_t& width,
                                uint32_t& height) {
    std::vector<const EvalRow*> shown;
    for (const EvalRow& r : rows)
        if (r.variant.figure) shown.push_back(&r);
    const uint32_t fw = truth.final.width, fh = truth.final.height;
    const uint32_t factor = std::clamp((fw + maxCellWidth - 1) / std::max(maxCellWidth, 1u), 1u, std::min(fw, fh));
    const uint32_t w = std::max(1u, fw / factor), h = std::max(1u, fh / factor), cols = uint32_t(shown.size()) + 1;
    auto cell = [&](const std::vector<uint8_t>& full) { return factor > 1 ? shrink(full, fw, fh, factor) : full; };
    width = w * cols + kGap * (cols - 1), height = h * 3 + kGap * 2;
    std::vector<uint8_t> out(size_t(width) * height * 4, 255);
    // One heat scale for every column, so that the maps compare: the largest of their 99th percentiles.
    heatScale = 0.0;
    for (const EvalRow* r : shown) {
        double s = 0.0;
        errorHeatMap(r->indirectImage, truth.indirect, truth.mask, s);
        heatScale = std::max(heatScale, s);
    }
    blit(out, width, cell(toneMap(truth.final, exposure)), w, h, 0, 0);
    blit(out, width, cell(toneMap(truth.indirect, indirectExposure)), w, h, 0, 1);
    blit(out, width, rampCell(w, h), w, h, 0, 2);
    for (uint32_t c = 0; c < shown.size(); ++c) {
        blit(out, width, cell(toneMap(shown[c]->final, exposure)), w, h, c + 1, 0);
        blit(out, width, cell(toneMap(shown[c]->indirectImage, indirectExposure)), w, h, c + 1, 1);
        double s = heatScale;
        blit(out, width, cell(errorHeatMap(shown[c]->indirectImage, truth.indirect, truth.mask, s)), w, h, c + 1, 2);
    }
    return out;
}

}  // namespace penumbra
