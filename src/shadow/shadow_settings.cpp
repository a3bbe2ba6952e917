#include "shadow/shadow_settings.h"

#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "shadow/shadow_options.h"

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

void validate(const ShadowSettings& s) { checkRanges(shadowOptions(), &s); }

}  // namespace penumbra
