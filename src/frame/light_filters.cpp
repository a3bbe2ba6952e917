#include "frame/light_filters.h"

#include <stdexcept>

#include <fmt/format.h>

#include "shadow/shadow_settings.h"

namespace penumbra {

std::pair<size_t, ShadowFilter> parseLightFilter(const std::string& spec) {
    const size_t eq = spec.find('=');
    const std::string index = spec.substr(0, eq);
    if (eq == std::string::npos || index.empty() || index.size() > 9 ||
        index.find_first_not_of("0123456789") != std::string::npos)
        throw std::invalid_argument("expected N=FILTER, e.g. 0=pcss");
    return {std::stoul(index), parseShadowFilter(spec.substr(eq + 1), spec)};
}

void applyLightFilters(const std::vector<std::string>& specs, std::vector<Light>& lights) {
    for (const std::string& spec : specs) {
        const auto [n, filter] = parseLightFilter(spec);
        if (n >= lights.size())
            throw std::invalid_argument(fmt::format("{}: the scene has {} light(s)", spec, lights.size()));
        lights[n].shadowFilter = filter;
    }
}

}  // namespace penumbra
