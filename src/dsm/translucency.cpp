#include "dsm/translucency.h"

#include <algorithm>
#include <cstring>
#include <string>

#include <fmt/format.h>

#include "core/raster.h"
#include "dsm/bindings.h"

namespace penumbra {
namespace {

// The pool must fit one storage-buffer descriptor (lavapipe: 128 MiB, 8.4M nodes).
uint64_t devicePoolLimit(vk::Context& ctx) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(ctx.physicalDevice(), &p);
    return std::max<uint64_t>(1, p.limits.maxStorageBufferRange / 16);
}

}  // namespace

CameraTranslucency::CameraTranslucency(vk::Allocator& alloc, SceneGpu& scene, const HairGpu* hair, uint32_t width,
                                       uint32_t height, bool computeHair)
    : alloc_(alloc), scene_(scene), hair_(hair), hasBlended_(scene.scene().hasBlendedMaterials()),
      casters_(scene.scene().translucentCasterBounds()), width_(width), height_(height) {
    if (!active()) return;
    vk::Context& ctx = alloc.context();
    const uint64_t pixels = uint64_t(width) * height;
    capacity_ = std::min(pixels * kNodesPerPixel, devicePoolLimit(ctx));
    const VkBufferUsageFlags usage =
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    heads_ = vk::Buffer(alloc, pixels * sizeof(uint32_t) * OIT_HEADER_UINTS, usage, false, "oit-heads");
    nodes_ = vk::Buffer(alloc, capacity_ * sizeof(glm::uvec4), usage, false, "oit-nodes");
    normals_ = vk::Buffer(alloc, capacity_ * sizeof(uint32_t), usage, false, "oit-normals");
    stats_ = vk::Buffer(alloc, sizeof(gpu::OitStats), usage, false, "oit-stats");
    bucketCount_ = depthBucketCount(ctx, pixels, kBuckets);
    buckets_ = vk::Buffer(alloc, pixels * sizeof(uint32_t) * bucketCount_, usage, false, "oit-buckets");
    tails_ = vk::Buffer(alloc, pixels * sizeof(uint64_t), usage, false, "oit-tails");
    layers_ = vk::Buffer(alloc, sizeof(glm::uvec4) + sizeof(glm::uvec2) * capacity_, usage, false,
                         "oit-kept-layers");  // a header, then (node, pixel) per kept node <= stored nodes
    shadeArgs_ = vk::Buffer(alloc, sizeof(glm::uvec4),  // core/indirect_args.comp's uvec4
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, false, "oit-shade-args");
    const size_t lights = std::max<size_t>(scene.scene().lights.size(), 1);
    hairShadow_ = vk::Buffer(alloc, hair_ ? VkDeviceSize(lights) * hair_->pointCount() * sizeof(float) : sizeof(float),
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, false, "oit-hair-shadow");

    createBuildPipelines(ctx, computeHair);
    createKernels(ctx);
    // The shadow map's samplers as shadow.filter makes them (the border reads as lit).
    nearest_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});
    border_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER, false, false});
    moments_ = vk::Sampler(ctx, {VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});
}

// Build set: the scene's draw set (set 1 its textures), the hair buffers, then nodes, normals,
// counters, the opaque depth, the depth buckets and the tails' sums (OIT_BUILD_*: both builds,
// raster and compute, write the runs there; oit.offsets writes the heads).
void CameraTranslucency::createBuildPipelines(vk::Context& ctx, bool computeHair) {
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    const std::vector<vk::Binding> lists{{OIT_BUILD_NODES, storage},        {OIT_BUILD_NORMALS, storage},
                                         {OIT_BUILD_STATS, storage},        {OIT_BUILD_OPAQUE_DEPTH, sampled},
                                         {OIT_BUILD_BUCKETS, storage},      {OIT_BUILD_TAILS, storage}};
    std::vector<vk::Binding> b = SceneGpu::drawSetBindings();
    for (const vk::Binding& h : HairGpu::bindings()) b.push_back(h);
    b.insert(b.end(), lists.begin(), lists.end());
    buildLayout_ = vk::DescriptorLayout(ctx, b);
    if (hair_ && computeHair)
        hairKernel_ = HairGpu::segmentKernel(ctx, "dsm/oit_hair.comp", lists, sizeof(gpu::OitBuildPush));
    else if (hair_)
        hairPipeline_ = vk::Pipeline::graphics(ctx, HairGpu::pipelineDesc("dsm/oit_hair.frag"),
                                               SceneGpu::drawLayouts(ctx, buildLayout_.handle()), sizeof(gpu::OitBuildPush));
    if (hasBlended_) {
        vk::GraphicsDesc d;
        d.vertexShader = "core/scene.vert";
        d.fragmentShader = "dsm/oit_mesh.frag";
        d.vertexStride = SceneGpu::vertexStride();
        d.vertexAttributes = SceneGpu::vertexAttributes();
        d.dynamicCullMode = true;  // single-sided blended surfaces are invisible from behind
        d.frontFace = SceneGpu::sceneFrontFace(true);
        meshPipeline_ = vk::Pipeline::graphics(ctx, d, SceneGpu::drawLayouts(ctx, buildLayout_.handle()), sizeof(gpu::OitBuildPush));
    }
}

void CameraTranslucency::createKernels(vk::Context& ctx) {
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                           uniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    offsets_ = vk::ComputeKernel(ctx, "dsm/oit_offsets.comp",
                                 std::vector<vk::Binding>{{OIT_OFFSETS_BUCKETS, storage},
                                                          {OIT_OFFSETS_STATS, storage},
                                                          {OIT_OFFSETS_HEADS, storage},
                                                          {OIT_OFFSETS_TAILS, storage}},
                                 sizeof(gpu::OitPush));
    sort_ = vk::ComputeKernel(ctx, "dsm/oit_sort.comp",
                              std::vector<vk::Binding>{{OIT_SORT_HEADS, storage}, {OIT_SORT_NODES, storage},
                                                       {OIT_SORT_NORMALS, storage}, {OIT_SORT_STATS, storage},
                                                       {OIT_SORT_LAYERS, storage}, {OIT_SORT_TAILS, storage},
                                                       {OIT_SORT_BUCKETS, storage}},
                              sizeof(gpu::OitPush));
    args_ = vk::ComputeKernel(ctx, "core/indirect_args.comp", {storage, storage}, sizeof(uint32_t));
    // The shade pass's bindings of lights, shadows and hair, which oit.hair-shadow shares.
    const std::vector<vk::Binding> shadows{
        {OIT_SHADE_FRAME, uniform},          {OIT_SHADE_LIGHTS, storage},         {OIT_SHADE_SHADOW_PARAMS, uniform},
        {OIT_SHADE_SHADOW_LAYERS, storage},  {DSM_LOOKUP_LIGHTS, storage},        {DSM_LOOKUP_HEADS, storage},
        {DSM_LOOKUP_NODES, storage},         {DSM_LOOKUP_SIDE, storage},          {OIT_SHADE_SHADOW_DEPTH, sampled},
        {OIT_SHADE_SHADOW_MOMENTS, sampled}, {OIT_SHADE_SHADOW_LIGHTS, storage},  {OIT_SHADE_HAIR_SHADOW, storage},
        {OIT_SHADE_HAIR_POINTS, storage}};
    std::vector<vk::Binding> shade = shadows;
    shade.insert(shade.end(), {{OIT_SHADE_LAYERS, storage}, {OIT_SHADE_NODES, storage}, {OIT_SHADE_NORMALS, storage},
                               {OIT_SHADE_INDIRECT, sampled}, {OIT_SHADE_SKY_IRRADIANCE, sampled}});
    shade_ = vk::ComputeKernel(ctx, "dsm/oit_shade.comp", shade, 0);
    if (hair_) {  // and the points' order
        std::vector<vk::Binding> hairShadow = shadows;
        hairShadow.push_back({OIT_HAIR_SHADOW_SPATIAL, storage});
        hairShadowKernel_ = vk::ComputeKernel(ctx, "dsm/oit_hair_shadow.comp", hairShadow, 0);
    }
    blend_ = vk::ComputeKernel(ctx, "dsm/oit_blend.comp",
                               std::vector<vk::Binding>{{OIT_BLEND_FRAME, uniform},
                                                        {OIT_BLEND_HEADS, storage},
                                                        {OIT_BLEND_LAYERS, storage},
                                                        {OIT_BLEND_NODES, storage},
                                                        {OIT_BLEND_HDR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}},
                               sizeof(gpu::OitPush));
}

// The depth buckets over the casters' window depths (their bounds' corners; 0 for a corner behind the
// eye): only how much the buckets leave out depends on it, not what is kept (dsm/depth_buckets.glsl).
gpu::OitBuildPush CameraTranslucency::cameraPush(const RibbonView& camera, const glm::mat4& viewProj,
                                                BuildStep step) const {
    glm::vec2 range{1.0f, 0.0f};
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec4 clip = viewProj * glm::vec4(casters_.corner(corner), 1.0f);
        const float depth = clip.w > 0.0f ? glm::clamp(clip.z / clip.w, 0.0f, 1.0f) : 0.0f;
        range = {std::min(range.x, depth), std::max(range.y, depth)};
    }
    return {0, 0, width_, 0, camera, depthBuckets(range, bucketCount_, step)};
}

void CameraTranslucency::recordBuild(VkCommandBuffer cmd, const gpu::OitBuildPush& cameraPush) const {
    beginRaster(cmd, {{width_, height_}, {}, VK_NULL_HANDLE});  // no attachments: the lists are the output
    gpu::OitBuildPush push = cameraPush;
    if (hairPipeline_.handle()) {
        hairPipeline_.bind(cmd);
        hair_->draw(cmd, hairPipeline_, push);
    }
    if (hasBlended_) {
        meshPipeline_.bind(cmd);  // same set layout: the pushed set stays bound
        scene_.draw(
            cmd,
            [&](const Draw& d) {
                push.material = d.material;
                meshPipeline_.push(cmd, push);
            },
            [](const Material& m) { return m.alphaMode == AlphaMode::Blend; });
    }
    vkCmdEndRendering(cmd);
}

void CameraTranslucency::addBuildTo(FrameGraph& graph, const RibbonView& camera, const glm::mat4& viewProj) {
    if (!active()) return;
    const BufferHandle heads = graph.import(heads_), nodes = graph.import(nodes_), normals = graph.import(normals_),
                       stats = graph.import(stats_), layers = graph.import(layers_), buckets = graph.import(buckets_),
                       tails = graph.import(tails_);
    // The counts and sums are zeroed here once; then oit.sort zeroes the pixels that had fragments.
    const bool zeroCounts = !countsZeroed_;
    countsZeroed_ = true;
    graph.pass("oit.clear", PassKind::Transfer)
        .use(stats, Use::TransferDst)
        .use(layers, Use::TransferDst)
        .use(buckets, Use::TransferDst)
        .use(tails, Use::TransferDst)
        .bytes(zeroCounts ? buckets_.size() + tails_.size() : 0)
        .record([stats, layers, buckets, tails, zeroCounts](PassContext& c) {
            vkCmdFillBuffer(c.cmd, c.buffer(stats).handle(), 0, VK_WHOLE_SIZE, 0);
            vkCmdFillBuffer(c.cmd, c.buffer(layers).handle(), 0, 16, 0);  // the kept layers' count
            if (!zeroCounts) return;
            vkCmdFillBuffer(c.cmd, c.buffer(buckets).handle(), 0, VK_WHOLE_SIZE, 0);
            vkCmdFillBuffer(c.cmd, c.buffer(tails).handle(), 0, VK_WHOLE_SIZE, 0);
        });
    lists_ = {nodes, normals, stats, buckets, tails};
    addBuildPasses(graph, cameraPush(camera, viewProj, BuildStep::Count), "oit.count");
    const gpu::OitPush push{width_, height_, uint32_t(capacity_), bucketCount_};
    graph.pass("oit.offsets")
        .pipeline(offsets_.pipeline)
        .storageBuffer(OIT_OFFSETS_BUCKETS, buckets, Use::StorageWrite)  // counts in, places out
        .storageBuffer(OIT_OFFSETS_STATS, stats, Use::StorageWrite)
        .storageBuffer(OIT_OFFSETS_HEADS, heads, Use::StorageWrite)  // each pixel's run
        .storageBuffer(OIT_OFFSETS_TAILS, tails)                     // which pixels have fragments
        .record([this, push](PassContext& c) {
            offsets_.pipeline.push(c.cmd, push);
            vkCmdDispatch(c.cmd, vk::divUp(width_, 8), vk::divUp(height_, 8), 1);
        });
    addBuildPasses(graph, cameraPush(camera, viewProj, BuildStep::Store), "oit.build");
}

// One step of the build: the raster (BLEND meshes, and hair without computeHair) and the compute
// hair, the same pipelines both steps, so that both make the same fragments.
void CameraTranslucency::addBuildPasses(FrameGraph& graph, const gpu::OitBuildPush& push, const std::string& name) {
    if (hasBlended_ || hairPipeline_.handle()) {
        PassBuilder build = graph.pass(name, PassKind::Raster);
        build.pipeline(hairPipeline_.handle() ? hairPipeline_ : meshPipeline_);
        scene_.declareDrawSet(build, graph.buffer("views"));
        if (hairPipeline_.handle()) hair_->declare(build);
        declareLists(build).record([this, push](PassContext& c) { recordBuild(c.cmd, push); });
    }
    if (hairKernel_.pipeline.handle()) {
        PassBuilder build = graph.pass(name + ".hair");
        build.pipeline(hairKernel_.pipeline).storageBuffer(HAIR_VIEWS, graph.buffer("views"));
        hair_->declare(build);
        declareLists(build).record([this, push](PassContext& c) { hair_->dispatchSegments(c.cmd, hairKernel_.pipeline, push); });
    }
}

// The lists of both builds (OIT_BUILD_*): the runs, the opaque depth they are tested against, the
// buckets and sums.
PassBuilder& CameraTranslucency::declareLists(PassBuilder& pass) const {
    return pass.storageBuffer(OIT_BUILD_NODES, lists_[0], Use::StorageWrite)
        .storageBuffer(OIT_BUILD_NORMALS, lists_[1], Use::StorageWrite)
        .storageBuffer(OIT_BUILD_STATS, lists_[2], Use::StorageWrite)
        .sampled(OIT_BUILD_OPAQUE_DEPTH, pass.graph().image("gbuffer.depth"), nearest_.handle())
        .storageBuffer(OIT_BUILD_BUCKETS, lists_[3], Use::StorageWrite)
        .storageBuffer(OIT_BUILD_TAILS, lists_[4], Use::StorageWrite);
}

// oit.sort (per pixel) -> oit.shade-args -> oit.shade (per kept layer, indirect) -> oit.blend (per pixel).
void CameraTranslucency::addCompositeTo(FrameGraph& graph) {
    if (!active()) return;
    const BufferHandle heads = graph.import(heads_), nodes = graph.import(nodes_), normals = graph.import(normals_),
                       layers = graph.import(layers_), args = graph.import(shadeArgs_);
    const gpu::OitPush push{width_, height_, uint32_t(capacity_), bucketCount_};
    const uint32_t groupsX = vk::divUp(width_, 8), groupsY = vk::divUp(height_, 8);
    if (hair_) addHairShadowTo(graph);
    graph.pass("oit.sort")
        .pipeline(sort_.pipeline)
        .storageBuffer(OIT_SORT_HEADS, heads, Use::StorageWrite)
        .storageBuffer(OIT_SORT_NODES, nodes, Use::StorageRead)
        .storageBuffer(OIT_SORT_NORMALS, normals, Use::StorageRead)
        .storageBuffer(OIT_SORT_STATS, graph.import(stats_), Use::StorageWrite)
        .storageBuffer(OIT_SORT_LAYERS, layers, Use::StorageWrite)
        .storageBuffer(OIT_SORT_TAILS, graph.import(tails_), Use::StorageWrite)  // read, then zeroed where not 0
        .storageBuffer(OIT_SORT_BUCKETS, graph.import(buckets_), Use::StorageWrite)  // zeroed with them
        .record([this, push, groupsX, groupsY](PassContext& c) {
            sort_.pipeline.push(c.cmd, push);
            vkCmdDispatch(c.cmd, groupsX, groupsY, 1);
        });
    graph.pass("oit.shade-args")
        .pipeline(args_.pipeline)
        .storageBuffer(0, layers, Use::StorageRead)
        .storageBuffer(1, args, Use::StorageWrite)
        .record([this](PassContext& c) {
            args_.pipeline.push(c.cmd, uint32_t(64));  // oit_shade.comp's workgroup
            vkCmdDispatch(c.cmd, 1, 1, 1);
        });
    PassBuilder shade = graph.pass("oit.shade");
    shade.pipeline(shade_.pipeline)
        .use(args, Use::IndirectArgs)
        .storageBuffer(OIT_SHADE_LAYERS, layers, Use::StorageRead)
        .storageBuffer(OIT_SHADE_NODES, nodes, Use::StorageWrite)
        .storageBuffer(OIT_SHADE_NORMALS, normals, Use::StorageRead)
        .sampled(OIT_SHADE_INDIRECT, graph.image("gi.irradiance"), nearest_.handle())
        .sampled(OIT_SHADE_SKY_IRRADIANCE, graph.image("sky.irradiance"), nearest_.handle())
        .storageBuffer(OIT_SHADE_HAIR_SHADOW, graph.import(hairShadow_))
        .storageBuffer(OIT_SHADE_HAIR_POINTS, hair_ ? graph.import(hair_->points()) : heads);  // no hair: never read
    declareShadows(shade).record([args](PassContext& c) { vkCmdDispatchIndirect(c.cmd, c.buffer(args).handle(), 0); });
    graph.pass("oit.blend")
        .pipeline(blend_.pipeline)
        .uniform(OIT_BLEND_FRAME, graph.buffer("frame"))
        .storageBuffer(OIT_BLEND_HEADS, heads, Use::StorageRead)
        .storageBuffer(OIT_BLEND_LAYERS, layers, Use::StorageRead)
        .storageBuffer(OIT_BLEND_NODES, nodes, Use::StorageRead)
        .storageImage(OIT_BLEND_HDR, graph.image("hdr"))
        .record([this, push, groupsX, groupsY](PassContext& c) {
            blend_.pipeline.push(c.cmd, push);
            vkCmdDispatch(c.cmd, groupsX, groupsY, 1);
        });
}

// What oit.shade and oit.hair-shadow both read: the frame, the lights, their shadow maps and deep
// shadow maps.
PassBuilder& CameraTranslucency::declareShadows(PassBuilder& pass) const {
    FrameGraph& graph = pass.graph();
    return pass.uniform(OIT_SHADE_FRAME, graph.buffer("frame"))
        .storageBuffer(OIT_SHADE_LIGHTS, graph.buffer("lights"))
        .uniform(OIT_SHADE_SHADOW_PARAMS, graph.buffer("shadow.params"))
        .storageBuffer(OIT_SHADE_SHADOW_LAYERS, graph.buffer("shadow.layers"))
        .storageBuffer(DSM_LOOKUP_LIGHTS, graph.buffer("dsm.lights"))
        .storageBuffer(DSM_LOOKUP_HEADS, graph.buffer("dsm.heads"))
        .storageBuffer(DSM_LOOKUP_NODES, graph.buffer("dsm.nodes"))
        .storageBuffer(DSM_LOOKUP_SIDE, graph.buffer("dsm.side"))
        .sampled(OIT_SHADE_SHADOW_DEPTH, graph.image("shadow.map"), border_.handle())
        .sampled(OIT_SHADE_SHADOW_MOMENTS, graph.image("shadow.moments"), moments_.handle())
        .storageBuffer(OIT_SHADE_SHADOW_LIGHTS, graph.buffer("shadow.lights"));
}

// One invocation per drawn hair point, in their Morton order.
void CameraTranslucency::addHairShadowTo(FrameGraph& graph) {
    PassBuilder pass = graph.pass("oit.hair-shadow");
    pass.pipeline(hairShadowKernel_.pipeline)
        .storageBuffer(OIT_SHADE_HAIR_SHADOW, graph.import(hairShadow_), Use::StorageWrite)
        .storageBuffer(OIT_SHADE_HAIR_POINTS, graph.import(hair_->points()))
        .storageBuffer(OIT_HAIR_SHADOW_SPATIAL, graph.import(hair_->spatialPoints()));
    declareShadows(pass).record([this](PassContext& c) { hair_->dispatchDrawnPoints(c.cmd); });
}

OitFrameStats CameraTranslucency::readStats(vk::CommandContext& cmd) const {
    OitFrameStats s;
    if (!active()) return s;
    gpu::OitStats g;
    const std::vector<uint8_t> bytes = cmd.readBuffer(stats_, sizeof(g));
    std::memcpy(&g, bytes.data(), sizeof(g));
    s.capacity = capacity_;
    s.fragments = g.fragments;
    s.leftOut = g.leftOut;
    s.overflow = g.overflow;
    s.kept = g.kept;
    s.beyondMaxList = g.beyondMaxList;
    s.longest = g.longest;
    s.poolBytes = capacity_ * kNodeBytes;
    return s;
}

std::string describeTranslucency(const OitFrameStats& s) {
    return fmt::format("translucency: {} camera fragments in front of the opaque surface, {} composited (longest "
                       "list {}, {} beyond the {}-fragment cap merged into one layer, {} of them in depth buckets "
                       "never stored); pool {:.1f} MiB for {} nodes",
                       s.fragments, s.kept, s.longest, s.beyondMaxList, OIT_MAX_LIST, s.leftOut,
                       double(s.poolBytes) / (1024.0 * 1024.0), s.capacity);
}

std::vector<std::string> translucencyWarnings(const OitFrameStats& s) {
    if (s.overflow == 0) return {};
    return {fmt::format("camera translucency node pool overflow: {} of {} translucent fragments dropped (pool of {} "
                        "nodes)",
                        s.overflow, s.fragments, s.capacity)};
}

}  // namespace penumbra
