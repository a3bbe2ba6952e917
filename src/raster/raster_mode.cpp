#include "raster/raster_mode.h"

#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace penumbra {

std::vector<std::string> rasterModeNames() { return {"hardware", "compute", "auto"}; }

RasterMode parseRasterMode(const std::string& name, const std::string& option) {
    const std::vector<std::string> names = rasterModeNames();
    for (size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return RasterMode(i);
    throw std::invalid_argument(
        fmt::format("{}: unknown rasterizer '{}' (one of: {})", option, name, fmt::join(names, ", ")));
}

std::string rasterModeName(RasterMode mode) { return rasterModeNames().at(size_t(mode)); }

// The auto rule, by device kind only: the hardware rasterizer everywhere, until the compute one is
// measured faster on a kind of device (README, "Compute rasterizer": the H100 measurements). CPU
// devices (lavapipe) rasterize on the CPU either way and keep the hardware path.
bool computeRasterFor(RasterMode mode, const VkPhysicalDeviceProperties& device) {
    (void)device;
    return mode == RasterMode::Compute;
}

}  // namespace penumbra
