#include "raster/compute_raster.h"

#include <algorithm>

#include "raster/bindings.h"
#include "vk/commands.h"

namespace penumbra {
namespace {

constexpr VkDescriptorType kBuffer = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
constexpr uint32_t kMaxGroups = 65535;  // the smallest maxComputeWorkGroupCount Vulkan allows

constexpr uint64_t kMaxRecords = 1u << 19;  // 64 MiB of triangle records

// The record capacity up to 2048^2: a quarter of the (triangle, layer) pairs may be large, each in 8
// tiles on average; every pair of a scene of up to 16384 gets a record (1.5 MiB; see smallExtent).
uint64_t baseRecordCapacity(uint64_t pairs) {
    return std::clamp<uint64_t>(std::max<uint64_t>(pairs / 4, std::min<uint64_t>(pairs, 16384)), 4096, kMaxRecords);
}

// A triangle's box grows with the layer's area, so the share of pairs that are large does too: from
// the base quarter at 2048^2 to every pair at 4096^2 and above (up to 256 MiB, within the device's
// storage-buffer range). Beyond the capacity, large triangles go to the overflow pass (correct, slower;
// never one thread per triangle).
uint32_t recordCapacityFor(uint64_t triangles, uint32_t layers, VkExtent2D size, uint64_t maxRange) {
    const uint64_t pairs = triangles * layers, base = baseRecordCapacity(pairs);
    const double growth = double(size.width) * size.height / (2048.0 * 2048.0);
    if (growth <= 1.0) return uint32_t(base);
    const uint64_t grown = std::min<uint64_t>(pairs, uint64_t(double(pairs / 4) * growth));
    const uint64_t cap = std::min<uint64_t>(uint64_t(1) << 21, maxRange / sizeof(gpu::RasterTriangle));
    return uint32_t(std::max(base, std::min(grown, cap)));
}

// The overflow queues (medium and huge, raster/overflow.comp): a slot per (triangle, layer) pair in
// each, so that neither can fill (16 MiB at most; a pair beyond is set up again by its setup thread,
// which then rasterizes its large triangles itself).
uint32_t overflowCapacityFor(uint64_t triangles, uint32_t layers) {
    return 2 * uint32_t(std::clamp<uint64_t>(triangles * layers, 1, 1u << 20));
}

// Tile entries: 8 per record, and at least 16 times every layer's tiles, so that a few triangles as
// large as a layer (a ground plane under a cascade) do not fill the list: one that does not fit goes
// to the overflow pass, which sets it up again. Above 4096^2 a triangle's box holds more tiles (as the
// layer's area), and so do the entries: up to 256 MiB within the device's range; 64 MiB up to 4096^2.
uint32_t entryCapacityFor(uint32_t records, VkExtent2D size, uint32_t layers, uint64_t maxRange) {
    const uint64_t tiles = uint64_t(vk::divUp(size.width, RASTER_TILE_SIZE)) * vk::divUp(size.height, RASTER_TILE_SIZE);
    const uint64_t wanted = std::max<uint64_t>(uint64_t(records) * 8, tiles * layers * 16);
    const double growth = double(size.width) * size.height / (4096.0 * 4096.0);
    if (growth <= 1.0) return uint32_t(std::min<uint64_t>(wanted, 1u << 23));
    const uint64_t cap = std::min<uint64_t>(uint64_t(1) << 25, maxRange / 8);
    return uint32_t(std::min<uint64_t>(uint64_t(double(wanted) * growth), std::max<uint64_t>(cap, 1u << 23)));
}

}  // namespace

ComputeRaster::ComputeRaster(vk::Allocator& alloc, SceneGpu& scene, VkExtent2D size, uint32_t layers, Views kind)
    : alloc_(alloc),
      scene_(scene),
      size_(size),
      kind_(kind),
      layers_(std::max(layers, 1u)),
      subpixelBits_(alloc.context().properties().limits.subPixelPrecisionBits),
      recordCapacity_(recordCapacityFor(scene.drawnTriangleCount(), layers_, size,
                                        alloc.context().properties().limits.maxStorageBufferRange)),
      entryCapacity_(entryCapacityFor(recordCapacity_, size, layers_,
                                      alloc.context().properties().limits.maxStorageBufferRange)),
      overflowCapacity_(overflowCapacityFor(scene.drawnTriangleCount(), layers_)) {
    vk::Context& ctx = alloc.context();
    const uint32_t pushBytes = sizeof(gpu::RasterPush);
    // The scene's draw set (set 1 its texture table); depth, records, tile entries, counters, tile
    // bins and lists, depth << 32 | ID (raster.glsl).
    std::vector<vk::Binding> tiles = SceneGpu::drawSetBindings();
    for (uint32_t b : {RASTER_SET_DEPTH, RASTER_SET_RECORDS, RASTER_SET_TILE_ENTRIES, RASTER_SET_COUNTERS,
                       RASTER_SET_TILE_BINS, RASTER_SET_TILE_LISTS, RASTER_SET_DEPTH_IDS})
        tiles.push_back({b, kBuffer});
    const std::vector<VkDescriptorSetLayout> table{SceneGpu::textureTableLayout(ctx)};
    const bool camera = kind == Views::Camera;
    std::vector<vk::Binding> fine = tiles;  // the layer table; then the target and ID images
    fine.push_back({RASTER_SET_LAYERS, kBuffer});
    tiles_ = vk::ComputeKernel(ctx, "raster/tiles.comp", fine, pushBytes, table);
    for (uint32_t b : {RASTER_SET_TARGET, RASTER_SET_ID_IMAGE}) fine.push_back({b, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE});
    tilesImage_ = vk::ComputeKernel(ctx, camera ? "raster/tiles_image_2d.comp" : "raster/tiles_image.comp", fine,
                                    pushBytes, table);
    bin_ = vk::ComputeKernel(ctx, "raster/bin.comp", tiles, pushBytes, table);
    scatter_ = vk::ComputeKernel(ctx, "raster/scatter.comp", tiles, pushBytes, table);
    place_ = vk::ComputeKernel(ctx, "raster/place.comp",
                               std::vector<vk::Binding>{{RASTER_PLACE_TILE_BINS, kBuffer}, {RASTER_PLACE_COUNTERS, kBuffer}},
                               sizeof(gpu::uvec4));
    std::vector<vk::Binding> setup = tiles;
    // vertices, indices, materials, layers, drawn triangles, the overflow queue
    for (uint32_t b : {RASTER_SET_VERTICES, RASTER_SET_INDICES, RASTER_SET_TRIANGLE_MATERIALS, RASTER_SET_LAYERS,
                       RASTER_SET_DRAWN_TRIANGLES, RASTER_SET_OVERFLOW_PAIRS})
        setup.push_back({b, kBuffer});
    setup_ = vk::ComputeKernel(ctx, "raster/setup.comp", setup, pushBytes, table);
    overflow_ = vk::ComputeKernel(ctx, "raster/overflow.comp", setup, pushBytes, table);
    args_ = vk::ComputeKernel(ctx, "raster/args.comp",
                              std::vector<vk::Binding>{{RASTER_ARGS_COUNTERS, kBuffer},
                                                       {RASTER_ARGS_DISPATCH, kBuffer},
                                                       {RASTER_ARGS_OVERFLOW_PAIRS, kBuffer}},
                              pushBytes);
    idSplit_ = vk::ComputeKernel(ctx, camera ? "raster/ids_2d.comp" : "raster/ids.comp",
                                 std::vector<vk::Binding>{{RASTER_IDS_DEPTH, kBuffer},
                                                          {RASTER_IDS_DEPTH_IDS, kBuffer},
                                                          {RASTER_IDS_LAYERS, kBuffer},
                                                          {RASTER_IDS_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}},
                                 pushBytes);
    // Bound as the ID image where a frame draws no layer with IDs into an R32_SFLOAT target.
    noIds_ = vk::Image(alloc, {VK_FORMAT_R32_UINT, 1, 1, 1, VK_IMAGE_USAGE_STORAGE_BIT, "raster-no-ids", 1, !camera});

    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    const VkBufferUsageFlags transfer = VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    depth_ = vk::Buffer(alloc, depthBytes(layerTexels(), layers_), storage | transfer, false, "raster-depth");
    records_ = vk::Buffer(alloc, VkDeviceSize(recordCapacity_) * sizeof(gpu::RasterTriangle), storage, false,
                          "raster-triangles");
    entries_ = vk::Buffer(alloc, VkDeviceSize(entryCapacity_) * sizeof(glm::uvec2), storage, false, "raster-tile-entries");
    tileBins_ = vk::Buffer(alloc, VkDeviceSize(binCount()) * sizeof(gpu::uvec4), storage | transfer, false,
                           "raster-tile-bins");
    tileLists_ = vk::Buffer(alloc, VkDeviceSize(entryCapacity_) * sizeof(uint32_t), storage, false, "raster-tile-lists");
    counters_ = vk::Buffer(alloc, sizeof(gpu::RasterCounters) + sizeof(Work), storage | transfer, false,
                           "raster-counters");
    overflowPairs_ = vk::Buffer(alloc, VkDeviceSize(overflowCapacity_) * sizeof(glm::uvec2), storage, false,
                               "raster-overflow-pairs");
    dispatchArgs_ = vk::Buffer(alloc, 4 * sizeof(gpu::uvec4), storage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, false,
                               "raster-dispatch");
    layerTable_ = vk::BufferRing(alloc, sizeof(gpu::RasterLayer) * layers_, storage, "raster-layers");
}

void ComputeRaster::setViews(const std::vector<RasterViews>& views, uint32_t slot) {
    views_ = views;
    std::vector<gpu::RasterLayer> rows;
    idLayers_ = 0;
    for (const RasterViews& v : views)
        for (uint32_t k = 0; k < v.layerCount; ++k) {
            const bool ids = v.firstIdLayer != RasterViews::kNoIds;
            rows.push_back({v.firstViewRow + k, v.firstLayer + k, v.skipBlended ? 1u : 0u,
                            ids ? v.firstIdLayer + k + 1 : 0u});
            if (ids) idLayers_ = std::max(idLayers_, v.firstIdLayer + k + 1);
        }
    if (rows.size() > layers_) throw std::invalid_argument("compute raster: more layers than it was made for");
    // Grown when a technique asks for more ID layers (a settings change: the renderer has waited for
    // the frames in flight); one unused element while none is drawn.
    const VkDeviceSize idBytes = depthIdBytes(layerTexels(), idLayers_);
    if (!depthIds_ || depthIds_.size() < idBytes)
        depthIds_ = vk::Buffer(alloc_, idBytes,
                               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, false,
                               "raster-depth-ids");
    layerRows_ = uint32_t(rows.size());
    layerTable_.select(slot);
    if (!rows.empty()) layerTable_.write(rows.data(), rows.size() * sizeof(rows[0]));
}

// The small-triangle threshold: where every (triangle, layer) pair has a record (scenes of few
// triangles: too few setup threads to keep the GPU busy while each rasterizes up to 16x16 pixels), half
// of it, so that more of them are binned to tiles. Only there: for large scenes the smaller threshold
// bins so many more triangles that the tile pass costs more than the setup saves, and at 4 the bins
// overflow (docs/techniques/shadows.md).
uint32_t ComputeRaster::smallExtent() const {
    const uint64_t pairs = uint64_t(scene_.drawnTriangleCount()) * layers_;
    return pairs <= baseRecordCapacity(pairs) ? RASTER_SMALL_EXTENT / 2 : RASTER_SMALL_EXTENT;
}

gpu::RasterPush ComputeRaster::push(RasterBias bias) const {
    const uint32_t triangles = scene_.drawnTriangleCount();
    gpu::RasterPush p{};
    p.width = size_.width;
    p.subpixelBits = subpixelBits_;
    p.triangleCount = triangles;
    p.layerCount = layerRows_;
    p.recordCapacity = recordCapacity_;
    p.entryCapacity = entryCapacity_;
    p.smallExtent = smallExtent();
    p.height = size_.height;
    p.biasConstant = bias.constant;
    p.biasSlope = bias.slope;
    p.frontsCounterClockwise = kind_ == Views::Camera ? 1u : 0u;
    return p;
}

// The setup pass (one thread per (triangle, layer)) and the overflow pass (one workgroup per queued
// pair and part of its large triangles, an indirect dispatch from args row 2): the same bindings.
PassBuilder ComputeRaster::addSetupPass(FrameGraph& graph, const std::string& name, BufferHandle viewRows,
                                        const vk::ComputeKernel& kernel, Use overflowQueue) {
    PassBuilder setup = graph.pass(name);
    setup.pipeline(kernel.pipeline);
    scene_.declareDrawSet(setup, viewRows);
    setup.storageBuffer(RASTER_SET_DEPTH, graph.import(depth_), Use::StorageWrite)
        .storageBuffer(RASTER_SET_DEPTH_IDS, graph.import(depthIds_), Use::StorageWrite)
        .storageBuffer(RASTER_SET_RECORDS, graph.import(records_), Use::StorageWrite)
        .storageBuffer(RASTER_SET_TILE_ENTRIES, graph.import(entries_), Use::StorageWrite)
        .storageBuffer(RASTER_SET_COUNTERS, graph.import(counters_), Use::StorageWrite)
        .storageBuffer(RASTER_SET_VERTICES, graph.import(scene_.vertices()))
        .storageBuffer(RASTER_SET_INDICES, graph.import(scene_.indices()))
        .storageBuffer(RASTER_SET_TRIANGLE_MATERIALS, graph.import(scene_.triangleMaterials()))
        .storageBuffer(RASTER_SET_LAYERS, graph.import(layerTable_.current()))
        .storageBuffer(RASTER_SET_DRAWN_TRIANGLES, graph.import(scene_.drawnTriangles()))
        .storageBuffer(RASTER_SET_TILE_BINS, graph.import(tileBins_), Use::StorageWrite)  // marks the tiles it draws into
        .storageBuffer(RASTER_SET_TILE_LISTS, graph.import(tileLists_), Use::StorageRead)  // in the layout, unused by setup
        .storageBuffer(RASTER_SET_OVERFLOW_PAIRS, graph.import(overflowPairs_), overflowQueue);
    return setup;
}

void ComputeRaster::addTo(FrameGraph& graph, const std::string& name, ImageHandle target, BufferHandle viewRows,
                          RasterBias bias, ImageHandle ids) {
    if (idLayers_ > 0 && !ids) throw std::invalid_argument("compute raster: views with ID layers but no ID image");
    if (layerRows_ == 0) return;  // every layer cached (ShadowMapPass): nothing to clear or draw
    const BufferHandle depth = graph.import(depth_), counters = graph.import(counters_),
                       args = graph.import(dispatchArgs_), depthIds = graph.import(depthIds_);
    graph.pass(name + ".clear", PassKind::Transfer)
        .use(depth, Use::TransferDst)
        .use(counters, Use::TransferDst)
        .use(depthIds, Use::TransferDst)
        .use(graph.import(tileBins_), Use::TransferDst)
        .record([this](PassContext& c) {
            vkCmdFillBuffer(c.cmd, depth_.handle(), 0, VK_WHOLE_SIZE, RASTER_FAR_BITS);
            vkCmdFillBuffer(c.cmd, counters_.handle(), 0, VK_WHOLE_SIZE, 0u);
            vkCmdFillBuffer(c.cmd, tileBins_.handle(), 0, VK_WHOLE_SIZE, 0u);
            const VkDeviceSize idBytes = layerTexels() * idLayers_ * 8;
            if (idBytes) vkCmdFillBuffer(c.cmd, depthIds_.handle(), 0, idBytes, RASTER_ID_CLEAR_BITS);
        });
    const gpu::RasterPush p = push(bias);
    addSetupPass(graph, name + ".setup", viewRows, setup_, Use::StorageWrite).record([this, p](PassContext& c) {
        setup_.pipeline.push(c.cmd, p);
        const uint32_t groups = std::min(vk::divUp(p.triangleCount, RASTER_SETUP_GROUP), kMaxGroups);
        vkCmdDispatch(c.cmd, groups, layerRows_, 1);
    });
    graph.pass(name + ".args")
        .pipeline(args_.pipeline)
        .storageBuffer(RASTER_ARGS_COUNTERS, counters, Use::StorageRead)
        .storageBuffer(RASTER_ARGS_DISPATCH, args, Use::StorageWrite)
        .storageBuffer(RASTER_ARGS_OVERFLOW_PAIRS, graph.import(overflowPairs_), Use::StorageRead)
        .record([this, p](PassContext& c) {
            args_.pipeline.push(c.cmd, p);
            vkCmdDispatch(c.cmd, 1, 1, 1);
        });
    addSetupPass(graph, name + ".overflow", viewRows, overflow_, Use::StorageRead)
        .use(args, Use::IndirectArgs)
        .record([this, p](PassContext& c) {  // the medium queue, then the huge one (args rows 2 and 3)
            overflow_.pipeline.push(c.cmd, p);
            vkCmdDispatchIndirect(c.cmd, dispatchArgs_.handle(), 2 * sizeof(gpu::uvec4));
            // Atomics only, but the queues' passes write the same buffers: ordered for the validation.
            const VkAccessFlags2 rw = VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
            vk::memoryBarrier(c.cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, rw, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, rw);
            vkCmdDispatchIndirect(c.cmd, dispatchArgs_.handle(), 3 * sizeof(gpu::uvec4));
        });
    addTileLists(graph, name, viewRows, p);
    addFineRaster(graph, name, viewRows, target, ids, p);
}

// One workgroup per tile of every layer drawn: straight into an R32_SFLOAT target and its ID image,
// or into the depth buffers, which the ID split and a copy into a D32_SFLOAT target then take.
void ComputeRaster::addFineRaster(FrameGraph& graph, const std::string& name, BufferHandle viewRows,
                                  ImageHandle target, ImageHandle ids, const gpu::RasterPush& p) {
    const bool intoTarget = graph.imageOf(target).format() == VK_FORMAT_R32_SFLOAT;
    const vk::ComputeKernel& kernel = intoTarget ? tilesImage_ : tiles_;
    PassBuilder tiles = graph.pass(name + ".tiles");
    tiles.pipeline(kernel.pipeline);
    declareRasterSet(tiles, graph, viewRows, Use::StorageRead);
    tiles.storageBuffer(RASTER_SET_DEPTH, graph.import(depth_), intoTarget ? Use::StorageRead : Use::StorageWrite)
        .storageBuffer(RASTER_SET_DEPTH_IDS, graph.import(depthIds_), intoTarget ? Use::StorageRead : Use::StorageWrite)
        .storageBuffer(RASTER_SET_LAYERS, graph.import(layerTable_.current()));
    if (intoTarget)
        tiles.storageImage(RASTER_SET_TARGET, target).storageImage(RASTER_SET_ID_IMAGE, ids ? ids : graph.import(noIds_));
    tiles.record([this, &kernel, p](PassContext& c) {
        kernel.pipeline.push(c.cmd, p);
        vkCmdDispatch(c.cmd, vk::divUp(size_.width, RASTER_TILE_SIZE), vk::divUp(size_.height, RASTER_TILE_SIZE),
                      layerRows_);
    });
    if (intoTarget) return;
    if (idLayers_ > 0) addIdSplit(graph, name, ids, p);
    addResolve(graph, name, target);
}

// The bindings every pass over the triangle records declares (raster.glsl), `lists` being how it uses
// the tile entries, bins and lists; depth (3, 16) is declared by each pass itself.
void ComputeRaster::declareRasterSet(PassBuilder& pass, FrameGraph& graph, BufferHandle viewRows, Use lists) const {
    scene_.declareDrawSet(pass, viewRows);
    pass.storageBuffer(RASTER_SET_RECORDS, graph.import(records_), Use::StorageRead)
        .storageBuffer(RASTER_SET_TILE_ENTRIES, graph.import(entries_), lists)
        .storageBuffer(RASTER_SET_COUNTERS, graph.import(counters_), Use::StorageRead)
        .storageBuffer(RASTER_SET_TILE_BINS, graph.import(tileBins_), lists)
        .storageBuffer(RASTER_SET_TILE_LISTS, graph.import(tileLists_), lists);
}

// Bin (one workgroup per large triangle: its tile entries and the tiles' counts), place (each tile's
// list placed in the list buffer), scatter (each entry's record into its tile's list).
void ComputeRaster::addTileLists(FrameGraph& graph, const std::string& name, BufferHandle viewRows,
                                 const gpu::RasterPush& p) {
    // Bin and scatter: indirect dispatches over the triangle records (args row 1) and the entries (row 0).
    auto listPass = [&](const char* suffix, const vk::ComputeKernel& k, VkDeviceSize argsOffset) {
        PassBuilder pass = graph.pass(name + suffix);
        pass.pipeline(k.pipeline);
        declareRasterSet(pass, graph, viewRows, Use::StorageWrite);
        pass.storageBuffer(RASTER_SET_DEPTH, graph.import(depth_), Use::StorageRead)
            .storageBuffer(RASTER_SET_DEPTH_IDS, graph.import(depthIds_), Use::StorageRead)
            .use(graph.import(dispatchArgs_), Use::IndirectArgs)
            .record([this, &k, p, argsOffset](PassContext& c) {
                k.pipeline.push(c.cmd, p);
                vkCmdDispatchIndirect(c.cmd, dispatchArgs_.handle(), argsOffset);
            });
    };
    listPass(".bin", bin_, sizeof(gpu::uvec4));
    const gpu::uvec4 bins{binCount(), 0, 0, 0};
    graph.pass(name + ".place")
        .pipeline(place_.pipeline)
        .storageBuffer(RASTER_PLACE_TILE_BINS, graph.import(tileBins_), Use::StorageWrite)
        .storageBuffer(RASTER_PLACE_COUNTERS, graph.import(counters_), Use::StorageWrite)
        .record([this, bins](PassContext& c) {
            place_.pipeline.push(c.cmd, bins);
            vkCmdDispatch(c.cmd, vk::divUp(bins.x, RASTER_PLACE_GROUP), 1, 1);
        });
    listPass(".scatter", scatter_, 0);
}

void ComputeRaster::addResolve(FrameGraph& graph, const std::string& name, ImageHandle target) {
    const BufferHandle depth = graph.import(depth_);
    graph.pass(name + ".resolve", PassKind::Transfer)
        .use(depth, Use::TransferSrc)
        .use(target, Use::TransferDst)
        .bytes(layerTexels() * layerRows_ * 8)
        .record([this, target](PassContext& c) {
            std::vector<VkBufferImageCopy> regions;
            const VkDeviceSize layerBytes = layerTexels() * 4;
            for (const RasterViews& v : views_) {
                VkBufferImageCopy r{};
                r.bufferOffset = layerBytes * v.firstLayer;
                r.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, v.firstLayer, v.layerCount};
                r.imageExtent = {size_.width, size_.height, 1};
                if (v.layerCount) regions.push_back(r);
            }
            vkCmdCopyBufferToImage(c.cmd, depth_.handle(), c.image(target).handle(),
                                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, uint32_t(regions.size()), regions.data());
        });
}

void ComputeRaster::addIdSplit(FrameGraph& graph, const std::string& name, ImageHandle ids, const gpu::RasterPush& p) {
    graph.pass(name + ".ids")
        .pipeline(idSplit_.pipeline)
        .storageBuffer(RASTER_IDS_DEPTH, graph.import(depth_), Use::StorageWrite)
        .storageBuffer(RASTER_IDS_DEPTH_IDS, graph.import(depthIds_), Use::StorageRead)
        .storageBuffer(RASTER_IDS_LAYERS, graph.import(layerTable_.current()))
        .storageImage(RASTER_IDS_IMAGE, ids)
        .bytes(layerTexels() * idLayers_ * 16)
        .record([this, p](PassContext& c) {
            idSplit_.pipeline.push(c.cmd, p);
            vkCmdDispatch(c.cmd, vk::divUp(size_.width, 8), vk::divUp(size_.height, 8), layerRows_);
        });
}

std::unique_ptr<DepthRaster> makeDepthRaster(vk::Allocator& alloc, SceneGpu& scene, VkExtent2D size, uint32_t layers,
                                             DepthRaster::Views kind) {
    return std::make_unique<ComputeRaster>(alloc, scene, size, layers, kind);
}

}  // namespace penumbra
