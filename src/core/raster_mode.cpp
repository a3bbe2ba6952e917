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
// same images): the compute rasterizer on NVIDIA H100 and H200 for layers up to kComputeMeasuredUpTo
// texels a side, the range the rasterizer sweep covered (bench/raster_sweep.sh, five scenes, three light
// kinds), where it was faster than the hardware at every point; the hardware above that and on every
// other device, CPU devices (lavapipe) included (docs/techniques/shadows.md).
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
