#include "eval/suite.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

namespace penumbra {

std::vector<SuiteScene> suiteScenes(const std::string& assets, const std::vector<std::string>& only) {
    // Sizes and paths per pixel: the reference's noise (relative L1 between two seeds) stays under
    // a third of the tightest target (0.15); the measured noise is in docs/evaluation.md.
    std::vector<SuiteScene> all{
        {"cornell", "cornell", "", {}, 128, 96, 4096},
        {"street", "street", "", {}, 128, 72, 4096},
        {"room", "room", "", {}, 128, 72, 4096},
        {"sponza", assets + "/sponza/glTF/Sponza.gltf", "-9,1.7,0.3,6,4.5,0,0,1,0,70", {"directional,0.1,-1,0.2,20"},
         128, 72, 4096},
        {"vc", assets + "/VC/glTF/VC.gltf", "14,9,16,0,1.5,0,0,1,0,50", {}, 128, 72, 4096},
    };
    if (only.empty()) return all;
    std::vector<SuiteScene> out;
    for (const std::string& name : only) {
        auto it = std::find_if(all.begin(), all.end(), [&](const SuiteScene& s) { return s.name == name; });
        if (it == all.end())
            throw std::invalid_argument(
                fmt::format("unknown suite scene '{}' (cornell, street, room, sponza, vc)", name));
        out.push_back(*it);
    }
    return out;
}

std::vector<EvalVariant> suiteVariants(const RenderSettings& base) {
    std::vector<EvalVariant> v;
    for (GiMode gi : {GiMode::Rsm, GiMode::Lpv}) {
        EvalVariant e{gi == GiMode::Rsm ? "rsm" : "lpv", "defaults", base, true};
        e.render.gi = gi;
        e.render.shadow.filter = ShadowFilter::Hard;
        v.push_back(e);
    }
    return v;
}

double regionRatio(const ImageF& a, const ImageF& b, const std::vector<uint8_t>& region) {
    double sa = 0.0, sb = 0.0;
    for (size_t i = 0; i < region.size(); ++i)
        if (region[i])
            for (int c = 0; c < 3; ++c) sa += a.rgba[i * 4 + c], sb += b.rgba[i * 4 + c];
    return sb > 0.0 ? sa / sb : std::numeric_limits<double>::quiet_NaN();
}

float autoExposure(const ImageF& image, const std::vector<uint8_t>& mask) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < size_t(image.width) * image.height; ++i)
        if (mask.empty() || mask[i]) sum += std::log(1e-6 + luminance(&image.rgba[i * 4])), ++n;
    if (n == 0) return 1.0f;
    return float(0.18 / std::exp(sum / double(n)));
}

std::string formatSuiteTable(const std::vector<SuiteResult>& results) {
    constexpr const char* kRow = "| {:<8} | {:>16} | {:>9} | {:>10} | {:>9} | {:>10} | {:>9} |\n";
    std::string out = fmt::format(kRow, "scene", "reference", "ref noise", "RSM rel L1", "RSM bias", "LPV rel L1",
                                  "LPV bias");
    out += fmt::format(kRow, "--------", "----------------", "--------:", "---------:", "--------:", "---------:",
                       "--------:");
    auto l1 = [](const EvalRow& r) { return fmt::format("{:.3f}", r.indirect.relL1); };
    auto bias = [](const EvalRow& r) { return fmt::format("{:+.1f}%", 100.0 * relativeBias(r.indirect)); };
    for (const SuiteResult& s : results)
        out += fmt::format(kRow, s.scene, fmt::format("{}x{} {} spp", s.width, s.height, s.spp),
                           fmt::format("{:.3f}", s.noiseL1), l1(s.rows[0]), bias(s.rows[0]), l1(s.rows[1]),
                           bias(s.rows[1]));
    return out;
}

nlohmann::json suiteJson(const std::vector<SuiteResult>& results) {
    nlohmann::json out = nlohmann::json::array();
    for (const SuiteResult& s : results) {
        nlohmann::json j{{"scene", s.scene}, {"width", s.width}, {"height", s.height}, {"spp", s.spp},
                         {"reference_noise_rel_l1", s.noiseL1}, {"rows", evalRowsJson(s.rows)}};
        if (s.ceilingLpv >= 0.0) j["ceiling_ratio"] = {{"rsm", s.ceilingRsm}, {"lpv", s.ceilingLpv}};
        out.push_back(j);
    }
    return out;
}

}  // namespace penumbra
