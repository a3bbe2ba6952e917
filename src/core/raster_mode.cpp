#include "core/raster_mode.h"

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

// The auto rule, by device kind and layer size, never by timing (one device and size always give the
// same images; README "Rasterizer choice"): the compute rasterizer on NVIDIA H100 and H200 for
// layers up to kComputeMeasuredUpTo texels a side, where it was measured faster than the hardware at
// every point of the sweep (H100: 2.0x to 16x; 512^2 to 8192^2 over five scenes, 16384^2 where the
// device takes it), the hardware above that and on every other device, CPU devices (lavapipe) included.
constexpr uint32_t kComputeMeasuredUpTo = 16384;

bool computeRasterFor(RasterMode mode, const VkPhysicalDeviceProperties& device, uint32_t layerSize) {
    if (mode != RasterMode::Auto) return mode == RasterMode::Compute;
    constexpr uint32_t kNvidia = 0x10DE;
    const std::string name = device.deviceName;
    const bool hopper = device.vendorID == kNvidia && device.deviceType == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU &&
                        (name.find("H100") != std::string::npos || name.find("H200") != std::string::npos);
    return hopper && layerSize <= kComputeMeasuredUpTo;
}

}  // namespace penumbra
