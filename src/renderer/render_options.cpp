#include "renderer/render_options.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "dsm/dsm_options.h"
#include "lighting/lighting_options.h"
#include "lpv/lpv_options.h"
#include "renderer/technique_registry.h"
#include "rsm/rsm_options.h"
#include "shadow/shadow_options.h"
#include "sky_light/sky_light_options.h"
#include "temporal_gi/temporal_gi_options.h"

namespace penumbra {
namespace {

using namespace change;
using S = RenderSettings;

const std::vector<std::pair<std::string, Aov>> kAovs{
    {"direct", Aov::Direct},         {"albedo", Aov::Albedo},       {"normal", Aov::Normal},
    {"depth", Aov::Depth},           {"shadow", Aov::Shadow},       {"final", Aov::Final},
    {"indirect", Aov::Indirect},     {"lpv-slice", Aov::LpvSlice},  {"gv-slice", Aov::GvSlice},
    {"cascade", Aov::Cascade},       {"transmittance", Aov::Transmittance}, {"dsm-lists", Aov::DsmLists},
    {"rsm-depth", Aov::RsmDepth},    {"rsm-normal", Aov::RsmNormal}, {"rsm-flux", Aov::RsmFlux},
    {"shadow-map", Aov::ShadowMap},  {"velocity", Aov::Velocity},   {"sky", Aov::Sky}};

// `--shadow pcf,dsm`: the opaque casters' filter and, optionally, deep shadow maps (dsm) or deep
// opacity maps (dom) for hair and blended meshes. One filter at most: `pcf,vsm` would keep the last.
void parseShadow(S& s, const std::string& value) {
    std::stringstream ss(value);
    std::string opaque;
    s.dsm.enabled = s.dsm.opacityMaps = false;
    for (std::string token; std::getline(ss, token, ',');) {
        if (token == "dsm" || token == "dom") {
            s.dsm.enabled = true;
            s.dsm.opacityMaps = token == "dom";
            continue;
        }
        const std::vector<std::string> names = shadowFilterNames();
        if (std::find(names.begin(), names.end(), token) == names.end())
            throw std::invalid_argument(fmt::format("unknown shadow filter '{}' (one of: {}; or dsm, dom)", token,
                                                    fmt::join(names, ", ")));
        if (!opaque.empty())
            throw std::invalid_argument(fmt::format("one filter for opaque casters ({} or {}), optionally with dsm "
                                                    "(e.g. {},dsm)", opaque, token, opaque));
        s.shadow.filter = parseShadowFilter(token, token);
        opaque = token;
    }
}

std::vector<std::string> shadowValue(const S& s) {
    std::string v = shadowFilterName(s.shadow.filter);
    if (s.dsm.enabled) v += s.dsm.opacityMaps ? ",dom" : ",dsm";
    return {v};
}

// A filter change re-assigns the lights' filters in place; deep shadow maps on or off rebuild what
// draws into or reads the shadow layers.
std::pair<SettingsChange, std::vector<std::string>> classifyShadow(const void* a, const void* b) {
    const S& x = *static_cast<const S*>(a);
    const S& y = *static_cast<const S*>(b);
    std::vector<std::string> parts;
    if (x.shadow.filter != y.shadow.filter) parts.push_back("shadow.filters");
    if (x.dsm.enabled != y.dsm.enabled) parts.insert(parts.end(), {"shadow", "gi", "dsm"});
    if (x.dsm.opacityMaps != y.dsm.opacityMaps) parts.push_back("dsm");
    return {parts.empty() ? SettingsChange::None : kStructure, parts};
}

// `--exposure auto|X`: auto (log-average luminance to middle grey) or a fixed linear multiplier.
void parseExposure(S& s, const std::string& value) {
    if (value == "auto") return void(s.autoExposure = true);
    size_t used = 0;
    double v = 0.0;
    try {
        v = std::stod(value, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != value.size() || !std::isfinite(v) || v < 1e-6 || v > 1e6)
        throw std::invalid_argument("expected auto or a multiplier in [1e-06, 1e+06]");
    s.autoExposure = false;
    s.exposure = float(v);
}

void addExposureRows(OptionTableBuilder<S>& t) {
    OptionRow& exposure = t.text(
        "--exposure", "exposure", [](S& s) -> auto& { return s.exposure; },
        [](const S& s) { return std::vector<std::string>{s.autoExposure ? "auto" : formatOptionNumber(s.exposure)}; },
        parseExposure, kFrame,
        "Exposure before tone mapping: auto (the log-average luminance of the geometry, sky excluded, maps to "
        "middle grey 0.18, adapting over frames) or a linear multiplier");
    exposure.placeholder = "auto|X";
    exposure.classify = [](const void* a, const void* b) {
        const S& x = *static_cast<const S*>(a);
        const S& y = *static_cast<const S*>(b);
        const bool same = x.autoExposure == y.autoExposure && x.exposure == y.exposure;
        return std::pair<SettingsChange, std::vector<std::string>>{same ? SettingsChange::None : kFrame, {}};
    };
    t.alsoWrites([](S& s) -> auto& { return s.autoExposure; });
    t.real("--exposure-compensation", "exposure_compensation", [](S& s) -> auto& { return s.exposureCompensation; },
           -20.0, 20.0, kFrame, "Exposure compensation in EV: the exposure (auto or fixed) times 2^EV");
}

void addOutputRows(OptionTableBuilder<S>& t) {
    t.integer("--width", "width", [](S& s) -> auto& { return s.width; }, 1, 16384, kSizes, "Image width")
        .rebuild({"camera", "gi"});
    t.integer("--height", "height", [](S& s) -> auto& { return s.height; }, 1, 16384, kSizes, "Image height")
        .rebuild({"camera", "gi"});
    t.choice("--aov", "aov", [](S& s) -> auto& { return s.aov; }, kAovs, kFrame,
             "Output: the final image or a debug view");
    t.integer("--aov-layer", "aov_layer", [](S& s) -> auto& { return s.aovLayer; }, 0, 4096, kFrame,
              "Layer shown by the rsm-depth/normal/flux and shadow-map AOVs");
    addExposureRows(t);
    t.choice("--camera-path", "camera_path", [](S& s) -> auto& { return s.cameraPath; },
             std::vector<std::pair<std::string, CameraPath>>{{"visibility", CameraPath::Visibility},
                                                             {"gbuffer", CameraPath::Gbuffer}},
             kStructure,
             "Camera G-buffer: visibility buffer (depth + triangle ID raster, albedo and normal resolved in "
             "compute) or the classic raster G-buffer")
        .rebuild({"camera"});
    t.boolean("--translucency", "translucency", [](S& s) -> auto& { return s.translucency; }, kStructure,
              "Hair and BLEND surfaces composited in depth order (off: drawn opaque)")
        .rebuild({"camera"});
    t.boolean("--overlap", "overlap", [](S& s) -> auto& { return s.overlapPasses; }, kFrame,
              "Independent passes run together, one barrier between dependent groups");
}

void addTechniqueRows(OptionTableBuilder<S>& t) {
    OptionRow& shadow = t.text(
        "--shadow", "shadow_filter", [](S& s) -> auto& { return s.shadow.filter; }, shadowValue, parseShadow, kStructure,
        "Shadow filter of every light: hard, pcf, pcss, vsm, evsm, msm; dsm (alone or e.g. pcf,dsm) adds deep "
        "shadow maps for hair and blended meshes, dom deep opacity maps for hair (for comparison)");
    shadow.inGroup(shadowOptions().title);
    shadow.classify = classifyShadow;
    shadow.placeholder = "FILTER[,dsm|dom]";
    t.alsoWrites([](S& s) -> auto& { return s.dsm.enabled; });
    t.alsoWrites([](S& s) -> auto& { return s.dsm.opacityMaps; });
    t.choice("--gi", "gi", [](S& s) -> auto& { return s.gi; },
             std::vector<std::pair<std::string, GiMode>>{{"none", GiMode::None}, {"rsm", GiMode::Rsm},
                                                         {"lpv", GiMode::Lpv}},
             kStructure, "Indirect light (one diffuse bounce)")
        .rebuild({"gi"});
    t.boolean("--gi-temporal", "gi_temporal", [](S& s) -> auto& { return s.giTemporal; }, kStructure,
              "Accumulate the indirect light over frames, reprojected, and filter it (off: each frame's own "
              "estimate)")
        .rebuild({"camera"});
}

OptionTable makeFrameTable() {
    OptionTableBuilder<S> t("frame", "Output: size, GI mode, debug view (AOV), exposure");
    addOutputRows(t);
    addTechniqueRows(t);
    return t.build();
}

template <class Member>
BoundOptionTable bind(const OptionTable& table, Member S::*member) {
    return {&table, [member](const S& s) -> const void* { return &(s.*member); }};
}

std::deque<BoundOptionTable>& tables() {
    static std::deque<BoundOptionTable> all{
        {&frameOptionTable(), [](const S& s) -> const void* { return &s; }},
        bind(shadowOptions(), &S::shadow),
        bind(dsmOptions(), &S::dsm),
        bind(rsmOptions(), &S::rsm),
        bind(lpvOptions(), &S::lpv),
        bind(temporalGiOptions(), &S::temporalGi),
        bind(skyLightOptions(), &S::skyLight),
        bind(lightingOptions(), &S::lighting),
    };
    // Techniques registered from outside src/ bring their tables (a deque: earlier entries stay put).
    static std::set<std::string> added;
    for (const TechniqueEntry& e : TechniqueRegistry::instance().entries())
        if (e.options && e.settings && added.insert(e.name).second)
            all.push_back({e.options, [where = e.settings](const S& s) -> const void* { return where(s); }});
    return all;
}

}  // namespace

const OptionTable& frameOptionTable() {
    static const OptionTable table = makeFrameTable();
    return table;
}

const std::deque<BoundOptionTable>& renderOptionTables() { return tables(); }


FoundOption findRenderOption(const std::string& flag) {
    for (const BoundOptionTable& t : renderOptionTables())
        if (const OptionRow* row = t.table->find(flag)) return {row, &t};
    return {};
}

void validateSettings(const RenderSettings& s) {
    checkRanges(frameOptionTable(), &s);
    validate(s.shadow);
    checkRanges(dsmOptions(), &s.dsm);
    validate(s.lighting);
    if (s.gi != GiMode::None) validate(s.rsm);
    if (s.gi == GiMode::Lpv) validate(s.lpv);
    if (s.giTemporal) validate(s.temporalGi);
    validate(s.skyLight);
    const OptionTable& frame = frameOptionTable();
    const std::string& aov = frame.flagOf<S>([](S& x) -> auto& { return x.aov; });
    const std::string& gi = frame.flagOf<S>([](S& x) -> auto& { return x.gi; });
    const OptionRow& aovRow = *frame.find(aov);
    const std::string view = aovRow.value(&s);
    auto need = [&](bool ok, const std::string& what) {
        if (!ok) throw std::invalid_argument(fmt::format("{} {} {}", aov, view, what));
    };
    const bool lpvView = s.aov == Aov::LpvSlice || s.aov == Aov::GvSlice;
    if (lpvView && s.gi != GiMode::Lpv)
        throw std::invalid_argument(fmt::format("{} lpv-slice/gv-slice need {} lpv", aov, gi));
    if (lpvView && s.lpv.sliceIndex >= s.lpv.resolution) {
        const OptionTable& lpv = lpvOptions();
        throw std::invalid_argument(fmt::format(
            "{} {} is outside the {} cells of {}", lpv.flagOf<LpvSettings>([](LpvSettings& x) -> auto& { return x.sliceIndex; }),
            s.lpv.sliceIndex, s.lpv.resolution, lpv.flagOf<LpvSettings>([](LpvSettings& x) -> auto& { return x.resolution; })));
    }
    // Indirect light without GI is black everywhere: an error rather than a silent black image.
    need(s.aov != Aov::Indirect || s.gi != GiMode::None, fmt::format("shows indirect light only: it needs {} rsm or {} lpv", gi, gi));
    const bool rsmView = s.aov == Aov::RsmDepth || s.aov == Aov::RsmNormal || s.aov == Aov::RsmFlux;
    need(!rsmView || s.gi != GiMode::None, fmt::format("needs {} rsm or {} lpv", gi, gi));
    if (s.gi == GiMode::Rsm && s.rsm.mode == RsmMode::AllTexels && s.rsm.resolution > 64) {
        const OptionTable& rsm = rsmOptions();
        throw std::invalid_argument(fmt::format(
            "{} all-texels gathers every texel at every pixel: use {} <= 64",
            rsm.flagOf<RsmSettings>([](RsmSettings& x) -> auto& { return x.mode; }),
            rsm.flagOf<RsmSettings>([](RsmSettings& x) -> auto& { return x.resolution; })));
    }
    const bool dsmView = s.aov == Aov::Transmittance || s.aov == Aov::DsmLists;
    need(!dsmView || s.dsm.enabled, fmt::format("needs deep shadow maps: add {} dsm",
                                                frame.flagOf<S>([](S& x) -> auto& { return x.shadow.filter; })));
}

nlohmann::json optionsJson(const OptionTable& table, const void* settings) {
    nlohmann::json out = nlohmann::json::object();
    for (const OptionRow& row : table.rows) {
        const std::vector<std::string> values = row.get(settings);
        auto one = [&](const std::string& v) -> nlohmann::json {
            if (row.kind == OptionKind::Integer) return std::stoll(v);
            if (row.kind == OptionKind::Real) return std::stod(v);
            if (row.kind == OptionKind::Bool) return v == "on";
            return v;
        };
        if (row.repeatable) {
            nlohmann::json list = nlohmann::json::array();
            for (const std::string& v : values) list.push_back(one(v));
            out[row.key] = list;
        } else {
            out[row.key] = values.empty() ? nlohmann::json() : one(values.front());
        }
    }
    return out;
}

nlohmann::json renderSettingsJson(const RenderSettings& settings) {
    nlohmann::json out = nlohmann::json::object();
    for (const BoundOptionTable& t : renderOptionTables()) {
        nlohmann::json values = optionsJson(*t.table, t.at(settings));
        if (t.table->module == "frame") out.update(values);
        else out[t.table->module] = values;
    }
    return out;
}

}  // namespace penumbra
