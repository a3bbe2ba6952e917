// The rasterizer a technique draws depth-only views with when the raster hardware does not (light
// layers, or the camera's depth and visibility IDs): the compute rasterizer, a shared service whose
// module (src/raster) implements this interface. Techniques reach it here and through
// makeDepthRaster, never through the raster module's headers.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/frame_graph.h"
#include "core/scene_gpu.h"

namespace penumbra {

// A run of target layers (e.g. every layer of one light), view row k for layer firstLayer + k.
struct RasterViews {
    uint32_t firstViewRow = 0;
    uint32_t firstLayer = 0;
    uint32_t layerCount = 0;
    bool skipBlended = false;  // alphaMode BLEND casters stay out (a deep shadow map takes them)
    // Layer k of the run also writes visibility IDs into layer firstIdLayer + k of the ID image.
    static constexpr uint32_t kNoIds = UINT32_MAX;
    uint32_t firstIdLayer = kNoIds;
};

struct RasterBias {
    float constant = 0.0f;  // Vulkan depthBiasConstantFactor
    float slope = 0.0f;     // depthBiasSlopeFactor
};

class DepthRaster {
public:
    // What it draws: light layers (y up, fronts clockwise, an array of ID layers), or the camera's
    // view (a y-flipped projection, fronts counter-clockwise: SceneGpu::sceneFrontFace; a 2D ID image).
    enum class Views { Light, Camera };
    virtual ~DepthRaster() = default;
    // Per frame: the layers to draw into this frame slot's table.
    virtual void setViews(const std::vector<RasterViews>& views, uint32_t slot) = 0;
    // The passes drawing the views set for this frame with the "views" rows of `viewRows` into
    // `target` (an R32_SFLOAT array with STORAGE usage, or a D32_SFLOAT one with TRANSFER_DST) and, for
    // views with ID layers, `ids` (R32_UINT, storage); `name` prefixes the pass names.
    virtual void addTo(FrameGraph& graph, const std::string& name, ImageHandle target, BufferHandle viewRows,
                       RasterBias bias, ImageHandle ids) = 0;
    void addTo(FrameGraph& graph, const std::string& name, ImageHandle target, BufferHandle viewRows, RasterBias bias) {
        addTo(graph, name, target, viewRows, bias, ImageHandle{});
    }
};

// The compute rasterizer (src/raster) for targets of `size` texels with up to `layers` layers.
std::unique_ptr<DepthRaster> makeDepthRaster(vk::Allocator& alloc, SceneGpu& scene, VkExtent2D size, uint32_t layers,
                                             DepthRaster::Views kind = DepthRaster::Views::Light);

}  // namespace penumbra
