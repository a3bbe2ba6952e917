#include "raster/raster_mode.h"

#include <stdexcept>
#include <string>

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

// The auto rule, by device kind only (never by timing, so one device always gives the same images):
// the compute rasterizer on the datacenter GPUs where it was measured faster on every scene (H100:
// Sponza's full frame 9.26 -> 5.80 ms, VC's 4.70 -> 3.53; README, "Compute rasterizer"), and on H200
// (the same Hopper die); the hardware everywhere else, CPU devices (lavapipe) included.
bool computeRasterFor(RasterMode mode, const VkPhysicalDeviceProperties& device) {
    if (mode != RasterMode::Auto) return mode == RasterMode::Compute;
    constexpr uint32_t kNvidia = 0x10DE;
    const std::string name = device.deviceName;
    return device.vendorID == kNvidia && device.deviceType == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU &&
           (name.find("H100") != std::string::npos || name.find("H200") != std::string::npos);
}

}  // namespace penumbra
