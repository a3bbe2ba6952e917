#include "shadow/shadow_settings.h"

#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace penumbra {

std::vector<std::string> shadowFilterNames() { return {"hard", "pcf", "pcss", "vsm", "evsm", "msm"}; }

ShadowFilter parseShadowFilter(const std::string& name, const std::string& option) {
    const std::vector<std::string> names = shadowFilterNames();
    for (size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return ShadowFilter(i + 1);
    throw std::invalid_argument(
        fmt::format("{}: unknown shadow filter '{}' (one of: {})", option, name, fmt::join(names, ", ")));
}

std::string shadowFilterName(ShadowFilter filter) {
    if (filter == ShadowFilter::Default) return "default";
    return shadowFilterNames().at(uint32_t(filter) - 1);
}

void validate(const ShadowSettings& s) {
    auto check = [](bool ok, const std::string& what) {
        if (!ok) throw std::invalid_argument(what);
    };
    check(s.resolution >= 16 && s.resolution <= 16384, fmt::format("shadow resolution {} is out of range (16..16384)", s.resolution));
    check(s.depthBiasConstant >= 0.0f && s.depthBiasConstant <= 1e6f, "constant depth bias must be in [0, 1e6]");
    check(s.depthBiasSlope >= 0.0f && s.depthBiasSlope <= 100.0f, "slope depth bias must be in [0, 100]");
    check(s.normalOffset >= 0.0f && s.normalOffset <= 100.0f, "normal offset must be in [0, 100] texels");
    check(s.cascades.count >= 1 && s.cascades.count <= 8, fmt::format("cascade count {} is out of range (1..8)", s.cascades.count));
    check(s.cascades.lambda >= 0.0f && s.cascades.lambda <= 1.0f, "cascade lambda must be in [0, 1]");
    check(s.cascades.blend >= 0.0f && s.cascades.blend <= 0.5f, "cascade blend band must be in [0, 0.5]");
    check(s.cascades.distance >= 0.0f && s.cascades.distance <= 1e9f, "cascade distance must not be negative");
    check(s.blurRadius <= 32, fmt::format("moment blur radius {} is out of range (0..32)", s.blurRadius));
    check(s.bleedReduction >= 0.0f && s.bleedReduction < 1.0f, "light-bleeding reduction must be in [0, 1)");
    check(s.pcfRadius >= 0.0f && s.pcfRadius <= 64.0f, "PCF radius must be in [0, 64] texels");
    check(s.pcssLightSize > 0.0f, "PCSS light size must be positive");
    check(s.pcssSunAngle > 0.0f && s.pcssSunAngle < 90.0f, "PCSS sun angle must be in (0, 90) degrees");
    check(s.pcssMaxRadius >= 1.0f && s.pcssMaxRadius <= 128.0f, "PCSS max radius must be in [1, 128] texels");
    check(s.evsmPositive > 0.0f && s.evsmPositive <= 42.0f && s.evsmNegative > 0.0f && s.evsmNegative <= 42.0f,
          "EVSM exponents must be in (0, 42] (32-bit float moments)");
    check(s.paraboloidMaxEdgeDegrees > 0.1f && s.paraboloidMaxEdgeDegrees <= 90.0f,
          "paraboloid edge angle must be in (0.1, 90] degrees");
}

}  // namespace penumbra
