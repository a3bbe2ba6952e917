#include "app/shadow_cli.h"

#include <map>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "app/option_checks.h"

namespace penumbra {
namespace {

// `--shadow` value: a filter name and/or "dsm" or "dom" (deep shadow maps or deep opacity maps for
// hair and blended meshes, which add to the filter of the opaque casters), comma separated.
// One filter for the opaque casters at most: `pcf,vsm` would silently keep the last.
void parseShadowOption(const std::string& value, ShadowFilter& filter, DsmSettings& deep) {
    std::stringstream ss(value);
    std::string opaque;
    for (std::string token; std::getline(ss, token, ',');) {
        if (token == "dsm" || token == "dom") {
            deep.enabled = true;
            deep.opacityMaps = token == "dom";
            continue;
        }
        try {
            filter = parseShadowFilter(token, "--shadow");
        } catch (const std::invalid_argument& e) {
            throw CLI::ValidationError(std::string(e.what()) + "; or dsm, dom");
        }
        if (!opaque.empty())
            throw CLI::ValidationError(fmt::format("--shadow {}: one filter for opaque casters ({} or {}), optionally "
                                                   "with dsm (e.g. {},dsm)", value, opaque, token, opaque));
        opaque = token;
    }
}

}  // namespace

void addShadowOptions(CLI::App& cmd, ShadowSettings& s, std::vector<std::string>& lightFilters, DsmSettings& deep) {
    cmd.add_option("--shadow-res", s.resolution, "Shadow map resolution")->check(CLI::Range(16, 16384));
    cmd.add_option("--shadow-bias-constant", s.depthBiasConstant, "Rasterizer constant depth bias")
        ->check(finiteRange(0.0, 1e6));
    cmd.add_option("--shadow-bias-slope", s.depthBiasSlope, "Rasterizer slope-scaled depth bias")
        ->check(finiteRange(0.0, 100.0));
    cmd.add_option("--shadow-normal-offset", s.normalOffset, "Receiver normal offset in shadow texels")
        ->check(finiteRange(0.0, 100.0));
    cmd.add_option_function<std::string>(
        "--shadow", [&s, &deep](const std::string& v) { parseShadowOption(v, s.filter, deep); },
        "Shadow filter of every light: hard, pcf, pcss, vsm, evsm, msm (default pcf); dsm (alone or e.g. pcf,dsm) adds "
        "deep shadow maps for hair and blended meshes, dom deep opacity maps for hair (for comparison)");
    cmd.add_option("--light-shadow", lightFilters, "Filter of one light, overriding --shadow: N=MODE (repeatable)");
    cmd.add_option("--pcf-radius", s.pcfRadius, "PCF kernel radius in shadow texels")
        ->check(finiteRange(0.0, 64.0));
    cmd.add_option("--pcss-light-size", s.pcssLightSize, "PCSS: spot/point light diameter, world units")
        ->check(finiteRange(1e-6, 1e6));
    cmd.add_option("--pcss-sun-angle", s.pcssSunAngle, "PCSS: directional light angular diameter, degrees")
        ->check(finiteRange(1e-4, 89.0));
    cmd.add_option("--pcss-max-radius", s.pcssMaxRadius, "PCSS: largest search/filter radius, texels")
        ->check(finiteRange(1.0, 128.0));
    cmd.add_option("--vsm-blur", s.blurRadius, "VSM/EVSM/MSM blur radius, texels")->check(CLI::Range(0, 32));
    cmd.add_option("--vsm-bleed", s.bleedReduction, "VSM/EVSM/MSM light-bleeding reduction in [0, 0.99]")
        ->check(finiteRange(0.0, 0.99));
    cmd.add_option("--cascades", s.cascades.count, "Directional lights: cascade count 1-8")
        ->check(CLI::Range(1, 8));
    cmd.add_option("--csm-lambda", s.cascades.lambda, "Cascade split: 0 uniform .. 1 logarithmic")
        ->check(finiteRange(0.0, 1.0));
    cmd.add_option("--csm-blend", s.cascades.blend, "Blend band between cascades, fraction")
        ->check(finiteRange(0.0, 0.5));
    cmd.add_option("--csm-distance", s.cascades.distance, "Shadowed view distance (0: the far plane)")
        ->check(finiteRange(0.0, 1e9));
    addChoice<RasterMode>(cmd, "--raster", s.raster,
                          {{"hardware", RasterMode::Hardware}, {"compute", RasterMode::Compute},
                           {"auto", RasterMode::Auto}},
                          "Who draws the shadow maps and the camera's visibility buffer: the raster hardware, the "
                          "compute rasterizer (paraboloid point lights stay on the hardware), or auto (by the "
                          "device's kind: compute on NVIDIA H100/H200, the hardware elsewhere)");
    addChoice<PointShadowMode>(cmd, "--point-shadow", s.pointMode,
                               {{"cube", PointShadowMode::Cube}, {"paraboloid", PointShadowMode::Paraboloid}},
                               "Point-light shadow maps: 6 cube faces or 2 paraboloids");
}

void applyLightFilters(const std::vector<std::string>& specs, std::vector<Light>& lights) {
    for (const std::string& spec : specs) {
        const size_t eq = spec.find('=');
        const std::string index = spec.substr(0, eq);
        if (eq == std::string::npos || index.empty() || index.size() > 9 ||
            index.find_first_not_of("0123456789") != std::string::npos)
            throw std::invalid_argument(fmt::format("--light-shadow {}: expected N=MODE, e.g. 0=pcss", spec));
        const unsigned long n = std::stoul(index);
        if (n >= lights.size())
            throw std::invalid_argument(
                fmt::format("--light-shadow {}: the scene has {} light(s)", spec, lights.size()));
        lights[n].shadowFilter = parseShadowFilter(spec.substr(eq + 1), "--light-shadow");
    }
}

}  // namespace penumbra
