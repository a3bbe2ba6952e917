// Resource sizes against the device, before anything is allocated: every large image and buffer the
// frame will create is estimated from the settings and the scene and checked against the device's
// limits (largest 2D image, array layers, storage-buffer range, allocation size, dispatch size) and
// its memory. A size that does not fit is one error line naming the option, the limit and the
// largest value of that option that fits, instead of a crash, a raw VK_ERROR_OUT_OF_DEVICE_MEMORY or
// silently wrong dispatches.
#pragma once
#include <cstdint>

#include <vector>

#include "renderer/render_settings.h"
#include "scene/scene.h"
#include "vk/context.h"

namespace penumbra {

// Throws std::invalid_argument. The memory check allows 90% of the largest device-local heap.
// `computeRaster`: the compute rasterizer draws the shadow layers (its depth buffers are bound whole).
// `lights`: the frame's lights (the scene's own, or those --light and the viewer give it).
void checkDeviceBudget(const vk::DeviceLimits& limits, const RenderSettings& settings, const Scene& scene,
                       const std::vector<Light>& lights, bool computeRaster = false);
void checkDeviceBudget(const vk::Context& ctx, const RenderSettings& settings, const Scene& scene,
                       const std::vector<Light>& lights);
inline void checkDeviceBudget(const vk::Context& ctx, const RenderSettings& settings, const Scene& scene) {
    checkDeviceBudget(ctx, settings, scene, scene.lights);
}

// The built-in hair scene's `--strands`, checked before the strands are grown: their ribbon points
// must fit one storage buffer and the device's memory.
void checkStrandBudget(const vk::DeviceLimits& limits, uint32_t strands);

// GPU bytes of one strand of the built-in hair scene (ribbon points and the strand record).
uint64_t hairBytesPerStrand();

}  // namespace penumbra
