// Which rasterizer draws depth-only light views: the hardware's (a layered depth-only raster pass)
// or the compute rasterizer (src/raster/compute_raster.h). `auto` picks by the device's kind and the
// layer size, never by timing, so that one device always gives the same images (computeRasterFor).
#pragma once
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace penumbra {

enum class RasterMode { Hardware, Compute, Auto };

// "hardware", "compute", "auto" (throws std::invalid_argument naming `option`).
RasterMode parseRasterMode(const std::string& name, const std::string& option);
std::string rasterModeName(RasterMode mode);
std::vector<std::string> rasterModeNames();

// Whether `mode` means the compute rasterizer on this device for layers of `layerSize`^2 texels (0: a
// size the rule does not look at). Auto: see raster_mode.cpp and docs/techniques/shadows.md.
bool computeRasterFor(RasterMode mode, const VkPhysicalDeviceProperties& device, uint32_t layerSize = 0);

}  // namespace penumbra
