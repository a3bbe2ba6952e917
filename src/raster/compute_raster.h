// The compute rasterizer for depth-only views (core/depth_raster.h): shadow-map layers drawn without
// the raster hardware, equal to it (same matrices, clipping, winding and culling, pixel centres, subpixel
// snapping, top-left rule, z/w plane, Vulkan's float depth bias, alpha-masked casters).
//   <name>.clear   fill the depth buffer with 1.0 and the bin counters with 0 (transfer)
//   <name>.setup   one thread per (triangle, layer), all layers in one dispatch: transform, clip,
//                  cull, snap; small triangles rasterized right there, large ones binned into tiles
//   <name>.args    the overflow, bin and scatter passes' indirect dispatch sizes
//   <name>.overflow large triangles that did not fit the lists: one workgroup per (triangle, part of at
//                  most RASTER_OVERFLOW_TILES tiles of its box), depth by atomicMin
//   <name>.bin     one workgroup per large triangle: which tiles of its box its edges may cover (an
//                  entry per tile), and a count per tile
//   <name>.place   each tile's list placed in the list buffer (its offset)
//   <name>.scatter one thread per entry: its triangle into its tile's list
//   <name>.tiles   one workgroup per tile of each layer: its list against depth kept in registers,
//                  written straight into an R32_SFLOAT target and the ID image (shadow maps, and the
//                  camera's depth unless a raster pass draws into it later); for a D32_SFLOAT target
//                  back into the depth buffers, then:
//   <name>.ids     layers with visibility IDs only: split depth << 32 | ID into the ID image and depth
//   <name>.resolve a copy of the depth buffer into the D32_SFLOAT target
// Small triangles (setup) take a 32-bit atomicMin on the float bits in a storage buffer (depths in
// [0, 1] order like their bits); layers with IDs (an RSM's, resolved from them) a 64-bit atomicMin of
// depth << 32 | ID, so one pass gives both, as the hardware's depth + R32_UINT colour pass does. The
// tile pass keeps the same minimum per pixel in registers. When a bin list is full its (triangle,
// layer) pair is queued for the overflow pass: slower, never wrong, and no thread's work grows with the
// layer's size (a setup thread tests at most RASTER_SMALL_EXTENT^2 pixels per triangle; one thread
// through a layer-sized triangle was the cost that did). See shaders/raster/; Laine & Karras (HPG 2011)
// for the binning and the tiled fine stage, Nanite for the small-triangle path.
#pragma once
#include <algorithm>
#include <vector>

#include "core/depth_raster.h"
#include "shared/types.h"

namespace penumbra {

class ComputeRaster final : public DepthRaster {
public:
    // Its buffers bound whole, shared with the device budget: depth (a float per texel of every layer)
    // and, for the layers with visibility IDs, depth << 32 | ID.
    static uint64_t depthBytes(uint64_t layerTexels, uint32_t layers) { return layerTexels * std::max(layers, 1u) * sizeof(float); }
    static uint64_t depthIdBytes(uint64_t layerTexels, uint32_t idLayers) {
        return std::max<uint64_t>(layerTexels * idLayers * sizeof(uint64_t), sizeof(uint64_t));
    }

    // Targets of `size` texels with up to `layers` layers.
    ComputeRaster(vk::Allocator& alloc, SceneGpu& scene, VkExtent2D size, uint32_t layers, Views kind = Views::Light);
    void setViews(const std::vector<RasterViews>& views, uint32_t slot) override;
    // The passes listed above (DepthRaster::addTo).
    using DepthRaster::addTo;
    void addTo(FrameGraph& graph, const std::string& name, ImageHandle target, BufferHandle viewRows, RasterBias bias,
               ImageHandle ids) override;

    // The work counters, after RasterCounters in the counters buffer (raster/raster.glsl).
    struct Work {
        uint32_t mostSetupPixels;     // the most pixels a setup thread tested for one triangle
        uint32_t overflowPairs;       // (triangle, layer) pairs queued for the overflow pass
        uint32_t mostOverflowPixels;  // the most pixels an overflow thread tested for one triangle
        uint32_t mostHugeTiles;       // the largest box (in tiles) of a pair in the huge queue
        uint32_t mediumPairs;         // queued pairs whose large triangles' boxes are small enough for one
                                      // workgroup each (at most RASTER_OVERFLOW_TILES tiles)
        uint32_t hugePairs;           // the others: split into parts of RASTER_OVERFLOW_TILES tiles
        uint32_t unused[2];
    };
    // Read-backs for tests: depth bits per texel (layer-major), and this frame's RasterCounters and Work.
    const vk::Buffer& depth() const { return depth_; }
    const vk::Buffer& counters() const { return counters_; }
    uint32_t recordCapacity() const { return recordCapacity_; }
    uint32_t smallExtent() const;  // RasterPush.smallExtent

private:
    gpu::RasterPush push(RasterBias bias) const;
    PassBuilder addSetupPass(FrameGraph& graph, const std::string& name, BufferHandle viewRows,
                             const vk::ComputeKernel& kernel, Use overflowQueue);
    void addFineRaster(FrameGraph& graph, const std::string& name, BufferHandle viewRows, ImageHandle target,
                       ImageHandle ids, const gpu::RasterPush& p);
    void addIdSplit(FrameGraph& graph, const std::string& name, ImageHandle ids, const gpu::RasterPush& p);
    void addResolve(FrameGraph& graph, const std::string& name, ImageHandle target);
    void addTileLists(FrameGraph& graph, const std::string& name, BufferHandle viewRows, const gpu::RasterPush& p);
    void declareRasterSet(PassBuilder& pass, FrameGraph& graph, BufferHandle viewRows, Use lists) const;
    // Tile bins: one per tile of every layer the targets have.
    uint32_t binCount() const {
        return vk::divUp(size_.width, RASTER_TILE_SIZE) * vk::divUp(size_.height, RASTER_TILE_SIZE) * layers_;
    }
    vk::Allocator& alloc_;
    SceneGpu& scene_;
    VkDeviceSize layerTexels() const { return VkDeviceSize(size_.width) * size_.height; }
    VkExtent2D size_;
    Views kind_;
    uint32_t layers_, subpixelBits_;
    uint32_t recordCapacity_, entryCapacity_, overflowCapacity_;
    vk::ComputeKernel setup_, overflow_, bin_, place_, scatter_, tiles_, tilesImage_, args_, idSplit_;
    vk::Buffer depth_, records_, entries_, tileBins_, tileLists_, counters_, overflowPairs_, dispatchArgs_;
    vk::Image noIds_;       // the ID image of frames without ID layers (R32_SFLOAT targets)
    vk::Buffer depthIds_;     // uint64 per texel of each ID layer, grown to the most requested
    uint32_t idLayers_ = 0;  // ID layers this frame's views write
    vk::BufferRing layerTable_;
    std::vector<RasterViews> views_;
    uint32_t layerRows_ = 0;
};

}  // namespace penumbra
