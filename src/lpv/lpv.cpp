#include "lpv/lpv.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <fmt/format.h>

#include "lpv/bindings.h"
#include "vk/format_bytes.h"

namespace penumbra {
namespace {

constexpr VkDescriptorType kTex = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kSsbo = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                           kUbo = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kImg = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
constexpr VkBufferUsageFlags kVolumeUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;

// What the passes' traffic estimates (PassBuilder::bytes) count: a cell of a light volume (RGB, four SH
// coefficients each), of the geometry volume (four coefficients), the corners a VPL is splatted over,
// an atomic maximum (a 4-byte read and write) and an atomic add to a fixed-point sum (8 bytes each way).
constexpr uint64_t kLightCellBytes = 3 * sizeof(glm::vec4);
constexpr uint64_t kGeometryCellBytes = sizeof(glm::vec4);
constexpr uint64_t kSplatCorners = 8;
constexpr uint64_t kAtomicMaxBytes = 2 * sizeof(uint32_t);
constexpr uint64_t kAtomicAddBytes = 2 * sizeof(int64_t);

using CascadePlacement = std::array<gpu::GpuLpvCascade, LPV_MAX_CASCADES>;

// Bytes of a texel of the image published as `name`.
uint64_t texelBytesOf(const FrameGraph& graph, const char* name) {
    return vk::texelBytes(graph.imageOf(graph.image(name)).format());
}

float maxExtent(const Bounds& b) {
    const glm::vec3 e = b.max - b.min;
    return std::max({e.x, e.y, e.z, 1e-3f});
}

}  // namespace

namespace {
// A room-sized scene: grids fit to the scene. A city: grids nested around the camera.
bool roomSized(const Bounds& scene) { return glm::length(scene.max - scene.min) < 20.0f; }
}  // namespace

uint32_t automaticCascadeCount(const Bounds&) {
    // Light goes about one cell per step: 8 steps in one grid leave most of a room dark. Each coarser
    // cascade carries it twice as far (docs/techniques/lpv.md), for every scene size.
    return 3u;
}

std::vector<gpu::GpuLpvCascade> placeCascades(const Bounds& scene, const glm::vec3& eye, uint32_t count,
                                              uint32_t resolution) {
    std::vector<gpu::GpuLpvCascade> out;
    const float extent = maxExtent(scene) * 1.02f;
    if (count == 1 || roomSized(scene)) {
        // The finest grid fit to the scene (a margin of half a cell on every side), each next one twice as
        // coarse around the same centre: they stay put whatever the camera does.
        for (uint32_t k = 0; k < count; ++k) {
            const float cell = extent / float(resolution - 1) * float(1u << k);
            out.push_back({scene.center() - 0.5f * cell * float(resolution), cell});
        }
        return out;
    }
    // Nested around the eye; the outermost is twice the scene so that it covers the scene from
    // anywhere inside it. Origins snap to whole cells, so static light stays put as the camera moves.
    for (uint32_t k = 0; k < count; ++k) {
        const float cell = 2.0f * extent / float(resolution) / float(1u << (count - 1 - k));
        const glm::vec3 origin = glm::floor(eye / cell - 0.5f * float(resolution)) * cell;
        out.push_back({origin, cell});
    }
    return out;
}

LightPropagationVolume::LightPropagationVolume(vk::Allocator& alloc, uint32_t width, uint32_t height,
                                               const LpvSettings& settings, const Bounds& bounds)
    : alloc_(alloc), settings_(settings), bounds_(bounds), width_(width), height_(height) {
    cascadeCount_ = settings_.cascades ? settings_.cascades : automaticCascadeCount(bounds);
    if (cascadeCount_ > LPV_MAX_CASCADES) throw vk::VulkanError("LPV: at most 4 cascades");
    if (settings_.rsmResolution % settings_.vplResolution)
        throw vk::VulkanError(fmt::format("LPV: the RSM resolution ({}) must be a multiple of the VPL resolution ({})",
                                          settings_.rsmResolution, settings_.vplResolution));
    vk::Context& ctx = alloc.context();
    const uint32_t push = sizeof(gpu::LpvPush);
    downsample_ = vk::ComputeKernel(ctx, "lpv/downsample.comp",
                                    {{LPV_DOWNSAMPLE_RSM_DEPTH, kTex}, {LPV_DOWNSAMPLE_RSM_NORMAL, kTex},
                                     {LPV_DOWNSAMPLE_RSM_FLUX, kTex}, {LPV_DOWNSAMPLE_LAYERS, kSsbo},
                                     {LPV_DOWNSAMPLE_LIGHTS, kSsbo}, {LPV_DOWNSAMPLE_VPLS, kSsbo}},
                                    push);
    injectRange_ = vk::ComputeKernel(ctx, "lpv/inject_range.comp",
                                     {{LPV_RANGE_VPLS, kSsbo}, {LPV_RANGE_RANGES, kSsbo}}, push);
    inject_ = vk::ComputeKernel(ctx, "lpv/inject.comp",
                                {{LPV_INJECT_VPLS, kSsbo}, {LPV_INJECT_LIGHT_SUMS, kSsbo},
                                 {LPV_INJECT_GEOMETRY_SUMS, kSsbo}, {LPV_INJECT_RANGES, kSsbo}},
                                push);
    injectCamera_ = vk::ComputeKernel(ctx, "lpv/inject_camera.comp",
                                      {{LPV_CAMERA_FRAME, kUbo}, {LPV_CAMERA_GBUFFER_NORMAL, kTex},
                                       {LPV_CAMERA_GBUFFER_DEPTH, kTex}, {LPV_CAMERA_GEOMETRY_SUMS, kSsbo}},
                                      push);
    injectSky_ = vk::ComputeKernel(ctx, "lpv/inject_sky.comp",
                                   {{LPV_SKY_FRAME, kUbo}, {LPV_SKY_GBUFFER_ALBEDO, kTex}, {LPV_SKY_GBUFFER_NORMAL, kTex},
                                    {LPV_SKY_GBUFFER_DEPTH, kTex}, {LPV_SKY_IRRADIANCE, kTex}, {LPV_SKY_VPLS, kSsbo}},
                                   push);
    resolve_ = vk::ComputeKernel(ctx, "lpv/resolve.comp",
                                 {{LPV_RESOLVE_LIGHT_SUMS, kSsbo}, {LPV_RESOLVE_GEOMETRY_SUMS, kSsbo},
                                  {LPV_RESOLVE_RANGES, kSsbo}, {LPV_RESOLVE_LIGHT, kSsbo},
                                  {LPV_RESOLVE_GEOMETRY, kSsbo}},
                                 push);
    propagate_ = vk::ComputeKernel(ctx, "lpv/propagate.comp",
                                   {{LPV_PROPAGATE_SOURCE, kSsbo}, {LPV_PROPAGATE_DESTINATION, kSsbo},
                                    {LPV_PROPAGATE_SUM, kSsbo}, {LPV_PROPAGATE_GEOMETRY, kSsbo},
                                    {LPV_PROPAGATE_FACES, kSsbo}},
                                   push);
    if (voxels())
        faceKernel_ = vk::ComputeKernel(ctx, "lpv/face_transmittance.comp",
                                        {{LPV_FACES_OCCUPANCY, kSsbo}, {LPV_FACES_OUT, kSsbo}}, push);
    gather_ = vk::ComputeKernel(ctx, "lpv/gather.comp",
                                {{LPV_GATHER_FRAME, kUbo}, {LPV_GATHER_GBUFFER_NORMAL, kTex},
                                 {LPV_GATHER_GBUFFER_DEPTH, kTex}, {LPV_GATHER_SUM, kSsbo},
                                 {LPV_GATHER_GEOMETRY, kSsbo}, {LPV_GATHER_IRRADIANCE, kImg}},
                                push);
    gradient_ = vk::ComputeKernel(ctx, "lpv/gradient.comp",
                                  {{LPV_GRADIENT_FRAME, kUbo}, {LPV_GRADIENT_GBUFFER_NORMAL, kTex},
                                   {LPV_GRADIENT_GBUFFER_DEPTH, kTex}, {LPV_GRADIENT_SUM, kSsbo},
                                   {LPV_GRADIENT_KEPT_SUM, kSsbo}, {LPV_GRADIENT_KEPT_CASCADES, kUbo},
                                   {LPV_GRADIENT_CHANGE, kImg}},
                                  push);
    pointSampler_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});

    const VkDeviceSize light = lpvLightVolumeBytes(settings_.resolution, cascadeCount_);
    const VkDeviceSize geometry = lpvGeometryVolumeBytes(settings_.resolution, cascadeCount_);
    volumeA_ = vk::Buffer(alloc, light, kVolumeUsage, false, "lpv-light-a");
    volumeB_ = vk::Buffer(alloc, light, kVolumeUsage, false, "lpv-light-b");
    // The sum of the steps in two halves: near (steps before the window of a coarser cascade) and far.
    accum_ = vk::Buffer(alloc, 2 * light, kVolumeUsage, false, "lpv-light-sum");
    geometry_ = vk::Buffer(alloc, geometry, kVolumeUsage, false, "lpv-geometry");
    if (voxels()) faces_ = vk::Buffer(alloc, geometry, kVolumeUsage, false, "lpv-faces");
    irradiance_ = vk::Image(alloc, {VK_FORMAT_R32G32B32A32_SFLOAT, width, height, 1,
                                    VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                        VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                    "lpv-irradiance"});
    push_.resolution = settings_.resolution;
    push_.cascadeCount = cascadeCount_;
    push_.rsmResolution = settings_.rsmResolution;
    push_.vplResolution = settings_.vplResolution;
    setSettings(settings_);
}

uint64_t lpvGradientBytes(uint64_t width, uint64_t height) {
    const uint64_t block = LPV_CHANGE_BLOCK, blocks = (width + block - 1) / block * ((height + block - 1) / block);
    return blocks * vk::texelBytes(GiChange::kFormat) + vk::kMaxFramesInFlight * sizeof(CascadePlacement);
}

void LightPropagationVolume::update(const glm::vec3& eye) {
    std::vector<gpu::GpuLpvCascade> c = placeCascades(bounds_, eye, cascadeCount_, settings_.resolution);
    for (uint32_t k = 0; k < cascadeCount_; ++k) push_.cascades[k] = c[k];
}

// One dispatch with this pass's push constants (its pipeline and set are bound by the graph).
void LightPropagationVolume::run(PassContext& c, const vk::ComputeKernel& kernel, const gpu::LpvPush& push,
                                 glm::uvec3 groups) {
    kernel.pipeline.push(c.cmd, push);
    vkCmdDispatch(c.cmd, groups.x, groups.y, groups.z);
}

void LightPropagationVolume::setSettings(const LpvSettings& settings) {
    settings_ = settings;
    changeTexel_.lagTolerance = settings.lagTolerance;
    push_.occlusion = settings.occlusion ? 1u : 0u;
    push_.blendCells = settings.blendCells;
    push_.cameraGeometryStep = settings.cameraGeometryStep;
    push_.voxelFaces = voxels() ? 1u : 0u;
}

void LightPropagationVolume::addTo(FrameGraph& graph, uint32_t rsmLayers, uint64_t occupancyGeneration,
                                   const GiAccumulation* accumulation, uint32_t slot) {
    // The sky's bounce: the camera's sky-lit surfels join the RSM's VPLs (while a sky is on).
    const uint32_t step = settings_.cameraGeometryStep;
    const uint32_t skySurfels =
        graph.hasImage("sky.irradiance") ? vk::divUp(width_, step) * vk::divUp(height_, step) : 0;
    if (layers_ != rsmLayers || skySurfels != skySurfels_) {
        layers_ = rsmLayers;
        skySurfels_ = skySurfels;
        const uint32_t n = settings_.vplResolution;
        vpls_ = vk::Buffer(alloc_, lpvVplBytes(n, layers_) + uint64_t(skySurfels) * sizeof(gpu::GpuVpl),
                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, false, "lpv-vpls");
        push_.vplCount = layers_ * n * n + skySurfels;
        push_.layerCount = layers_;
    }
    // The gradient compares with the kept volume only in a frame that adds to the history it kept it for.
    const bool keep = accumulation != nullptr;
    const bool kept = keep && keepLastSum();
    const bool measure = kept && accumulation->accumulating;
    if (!keep) kept_.valid = false;
    if (layers_ > 0) addDownsample(graph);
    if (layers_ > 0 && skySurfels_ > 0) addSkySurfels(graph);
    addInjection(graph);
    addCameraGeometry(graph);
    addResolve(graph);
    addPropagation(graph, occupancyGeneration);
    if (measure) addGradient(graph, slot);
    addGather(graph);
    if (keep) {
        kept_ = {true, settings_.resolution, cascadeCount_, {}};
        std::copy_n(push_.cascades, cascadeCount_, kept_.cascades.begin());
    }
}

// While a history is kept, the sum buffers swap: this frame fills one, the other keeps last frame's.
// Made on the first such frame (the device budget counts them while --gi-temporal is on).
bool LightPropagationVolume::keepLastSum() {
    if (!keptAccum_) {
        keptAccum_ = vk::Buffer(alloc_, accum_.size(), kVolumeUsage, false, "lpv-light-sum");
        keptCascades_ = vk::BufferRing(alloc_, sizeof(CascadePlacement), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                       "lpv-kept-cascades");
        change_ = vk::Image(alloc_, {GiChange::kFormat, vk::divUp(width_, uint32_t(LPV_CHANGE_BLOCK)),
                                     vk::divUp(height_, uint32_t(LPV_CHANGE_BLOCK)), 1,
                                     VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                         VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                     "lpv-change"});
    }
    std::swap(accum_, keptAccum_);
    // The same grids (a size change builds a new volume, so this holds; checked all the same).
    return kept_.valid && kept_.resolution == settings_.resolution && kept_.cascadeCount == cascadeCount_;
}

void LightPropagationVolume::setVpls(vk::CommandContext& cmd, const std::vector<gpu::GpuVpl>& vpls) {
    vpls_ = cmd.createDeviceBuffer(vpls.data(), vpls.size() * sizeof(gpu::GpuVpl),
                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "lpv-vpls");
    layers_ = 1;
    push_.vplCount = uint32_t(vpls.size());
}

void LightPropagationVolume::addPropagationFromVpls(FrameGraph& graph) {
    addInjection(graph);
    addResolve(graph);
    addPropagation(graph);
}

void LightPropagationVolume::addDownsample(FrameGraph& graph) {
    const VkSampler point = pointSampler_.handle();
    // Each RSM texel read once (depth, normal, flux), each VPL written once.
    const uint64_t texels = uint64_t(settings_.rsmResolution) * settings_.rsmResolution * layers_;
    const uint64_t texelBytes = texelBytesOf(graph, "rsm.depth") + texelBytesOf(graph, "rsm.normal") +
                                texelBytesOf(graph, "rsm.flux");
    const uint32_t n = vk::divUp(settings_.vplResolution, 8);
    graph.pass("lpv.downsample")
        .pipeline(downsample_.pipeline)
        .sampled(LPV_DOWNSAMPLE_RSM_DEPTH, graph.image("rsm.depth"), point)
        .sampled(LPV_DOWNSAMPLE_RSM_NORMAL, graph.image("rsm.normal"), point)
        .sampled(LPV_DOWNSAMPLE_RSM_FLUX, graph.image("rsm.flux"), point)
        .storageBuffer(LPV_DOWNSAMPLE_LAYERS, graph.buffer("rsm.layers"))
        .storageBuffer(LPV_DOWNSAMPLE_LIGHTS, graph.buffer("lights"))
        .storageBuffer(LPV_DOWNSAMPLE_VPLS, graph.import(vpls_), Use::StorageWrite)
        .bytes(texels * texelBytes + uint64_t(push_.vplCount) * sizeof(gpu::GpuVpl))
        .record([this, push = push_, n](PassContext& c) { run(c, downsample_, push, {n, n, layers_}); });
}

void LightPropagationVolume::addInjection(FrameGraph& graph) {
    // The fixed-point sums live in the sum buffer and volume B until the first step (lpv/volume.glsl).
    const BufferHandle lightSums = graph.import(accum_), geometrySums = graph.import(volumeB_);
    graph.pass("lpv.clear", PassKind::Transfer)
        .use(lightSums, Use::TransferDst)
        .use(geometrySums, Use::TransferDst)
        .bytes(accum_.size() + volumeB_.size())
        .record([lightSums, geometrySums](PassContext& c) {
            for (BufferHandle h : {lightSums, geometrySums})
                vkCmdFillBuffer(c.cmd, c.buffer(h).handle(), 0, VK_WHOLE_SIZE, 0);
        });
    if (layers_ == 0) return;
    const BufferHandle vpls = graph.import(vpls_);
    const uint32_t groups = vk::divUp(push_.vplCount, 64);
    // Each VPL read once; per cascade and splat corner 3 atomic maxima.
    graph.pass("lpv.inject-range")
        .pipeline(injectRange_.pipeline)
        .storageBuffer(LPV_RANGE_VPLS, vpls)
        .storageBuffer(LPV_RANGE_RANGES, geometrySums, Use::StorageWrite)
        .bytes(uint64_t(push_.vplCount) * (sizeof(gpu::GpuVpl) + cascadeCount_ * kSplatCorners * 3 * kAtomicMaxBytes))
        .record([this, push = push_, groups](PassContext& c) { run(c, injectRange_, push, {groups, 1, 1}); });
    // Each VPL read once; per cascade and splat corner 3 scales read and 12 atomic adds (RGB SH), and
    // 4 atomic adds for the geometry.
    graph.pass("lpv.inject")
        .pipeline(inject_.pipeline)
        .storageBuffer(LPV_INJECT_VPLS, vpls)
        .storageBuffer(LPV_INJECT_LIGHT_SUMS, lightSums, Use::StorageWrite)
        .storageBuffer(LPV_INJECT_GEOMETRY_SUMS, geometrySums, Use::StorageWrite)
        .storageBuffer(LPV_INJECT_RANGES, geometrySums)
        .bytes(uint64_t(push_.vplCount) *
               (sizeof(gpu::GpuVpl) +
                cascadeCount_ * (kSplatCorners * (3 * sizeof(float) + 12 * kAtomicAddBytes) + 4 * kAtomicAddBytes)))
        .record([this, push = push_, groups](PassContext& c) { run(c, inject_, push, {groups, 1, 1}); });
}

// The fixed-point sums to the float light volume A and the geometry volume.
void LightPropagationVolume::addResolve(FrameGraph& graph) {
    const uint32_t r = settings_.resolution;
    const BufferHandle sums = graph.import(volumeB_);
    graph.pass("lpv.resolve")
        .pipeline(resolve_.pipeline)
        .storageBuffer(LPV_RESOLVE_LIGHT_SUMS, graph.import(accum_))
        .storageBuffer(LPV_RESOLVE_GEOMETRY_SUMS, sums)
        .storageBuffer(LPV_RESOLVE_RANGES, sums)
        .storageBuffer(LPV_RESOLVE_LIGHT, graph.import(volumeA_), Use::StorageWrite)
        .storageBuffer(LPV_RESOLVE_GEOMETRY, graph.import(geometry_), Use::StorageWrite)
        .bytes(accum_.size() + volumeB_.size() + volumeA_.size() + geometry_.size())
        .record([this, push = push_, r](PassContext& c) {
            run(c, resolve_, push, {vk::divUp(r, 4), vk::divUp(r, 4), vk::divUp(r * cascadeCount_, 4)});
        });
}

void LightPropagationVolume::addSkySurfels(FrameGraph& graph) {
    const VkSampler point = pointSampler_.handle();
    const uint32_t step = settings_.cameraGeometryStep;
    const glm::uvec3 groups{vk::divUp(vk::divUp(width_, step), 8), vk::divUp(vk::divUp(height_, step), 8), 1};
    graph.pass("lpv.inject-sky")
        .pipeline(injectSky_.pipeline)
        .uniform(LPV_SKY_FRAME, graph.buffer("frame"))
        .sampled(LPV_SKY_GBUFFER_ALBEDO, graph.image("gbuffer.albedo"), point)
        .sampled(LPV_SKY_GBUFFER_NORMAL, graph.image("gbuffer.normal"), point)
        .sampled(LPV_SKY_GBUFFER_DEPTH, graph.image("gbuffer.depth"), point)
        .sampled(LPV_SKY_IRRADIANCE, graph.image("sky.irradiance"), point)
        .storageBuffer(LPV_SKY_VPLS, graph.import(vpls_), Use::StorageWrite)
        .record([this, push = push_, groups](PassContext& c) { run(c, injectSky_, push, groups); });
}

void LightPropagationVolume::addCameraGeometry(FrameGraph& graph) {
    if (!settings_.cameraGeometry || !settings_.occlusion || voxels()) return;
    const VkSampler point = pointSampler_.handle();
    const uint32_t step = settings_.cameraGeometryStep;
    const glm::uvec3 groups{vk::divUp(vk::divUp(width_, step), 8), vk::divUp(vk::divUp(height_, step), 8), 1};
    graph.pass("lpv.inject-camera")
        .pipeline(injectCamera_.pipeline)
        .uniform(LPV_CAMERA_FRAME, graph.buffer("frame"))
        .sampled(LPV_CAMERA_GBUFFER_NORMAL, graph.image("gbuffer.normal"), point)
        .sampled(LPV_CAMERA_GBUFFER_DEPTH, graph.image("gbuffer.depth"), point)
        .storageBuffer(LPV_CAMERA_GEOMETRY_SUMS, graph.import(volumeB_), Use::StorageWrite)
        .record([this, push = push_, groups](PassContext& c) { run(c, injectCamera_, push, groups); });
}

void LightPropagationVolume::addPropagation(FrameGraph& graph, uint64_t occupancyGeneration) {
    const uint32_t r = settings_.resolution;
    const BufferHandle a = graph.import(volumeA_), b = graph.import(volumeB_), sum = graph.import(accum_),
                       geometry = graph.import(geometry_);
    const BufferHandle faces = voxels() ? graph.import(faces_) : geometry;  // unread without voxels
    // The faces stay valid while the voxels and the cascades do (a room-sized scene's grids never move).
    std::array<gpu::GpuLpvCascade, LPV_MAX_CASCADES> cascades{};
    std::copy_n(push_.cascades, cascadeCount_, cascades.begin());
    const auto facesOf = std::make_pair(occupancyGeneration, cascades);
    const bool sameFaces = facesOf_ && facesOf_->first == facesOf.first &&
                           std::memcmp(facesOf_->second.data(), cascades.data(), sizeof(cascades)) == 0;
    if (voxels() && !sameFaces) {
        facesOf_ = facesOf;
        graph.pass("lpv.faces")
            .pipeline(faceKernel_.pipeline)
            .storageBuffer(LPV_FACES_OCCUPANCY, graph.buffer("occupancy"))
            .storageBuffer(LPV_FACES_OUT, faces, Use::StorageWrite)
            .record([this, push = push_, r](PassContext& c) {
                run(c, faceKernel_, push, {vk::divUp(r, 4), vk::divUp(r, 4), vk::divUp(r * cascadeCount_, 4)});
            });
    }
    for (uint32_t i = 0; i < settings_.iterations; ++i) {
        gpu::LpvPush push = push_;
        push.iteration = i;
        // A coarser cascade's far half starts where the finer one's steps end: after half its steps
        // (cells twice as large), light has gone as far as the finer cascade's last step took it.
        push.farFromIteration = std::max(1u, (settings_.iterations + 1) / 2);
        // Per cell, once: the source, the geometry, the destination, the running sum read and written.
        graph.pass(fmt::format("lpv.propagate[{}]", i))
            .pipeline(propagate_.pipeline)
            .storageBuffer(LPV_PROPAGATE_SOURCE, i % 2 ? b : a, Use::StorageRead)
            .storageBuffer(LPV_PROPAGATE_DESTINATION, i % 2 ? a : b, Use::StorageWrite)
            .storageBuffer(LPV_PROPAGATE_SUM, sum, Use::StorageWrite)
            .storageBuffer(LPV_PROPAGATE_GEOMETRY, geometry, Use::StorageRead)
            .storageBuffer(LPV_PROPAGATE_FACES, faces, Use::StorageRead)
            .bytes(uint64_t(r) * r * r * cascadeCount_ * (4 * kLightCellBytes + kGeometryCellBytes))
            .record([this, push, r](PassContext& c) {
                run(c, propagate_, push, {vk::divUp(r, 4), vk::divUp(r, 4), vk::divUp(r * cascadeCount_, 4)});
            });
    }
}

// Temporal gradients (lpv/gradient.comp): per block of the change image, the centre pixel's irradiance
// from this frame's volume and from the kept one, at its own placement (the cascades follow the
// camera); published with names::kGiChange, which temporal_gi weighs its history by.
void LightPropagationVolume::addGradient(FrameGraph& graph, uint32_t slot) {
    keptCascades_.select(slot);
    keptCascades_.write(kept_.cascades.data(), sizeof(CascadePlacement));
    const VkSampler point = pointSampler_.handle();
    const ImageHandle change = graph.import(change_);
    const glm::uvec3 groups{vk::divUp(change_.width(), 8u), vk::divUp(change_.height(), 8u), 1};
    // Per block: a pixel's depth and normal read, a change texel written; both summed volumes read once.
    const uint64_t blockBytes = texelBytesOf(graph, "gbuffer.depth") + texelBytesOf(graph, "gbuffer.normal") +
                                vk::texelBytes(GiChange::kFormat);
    graph.pass("lpv.gradient")
        .pipeline(gradient_.pipeline)
        .uniform(LPV_GRADIENT_FRAME, graph.buffer("frame"))
        .sampled(LPV_GRADIENT_GBUFFER_NORMAL, graph.image("gbuffer.normal"), point)
        .sampled(LPV_GRADIENT_GBUFFER_DEPTH, graph.image("gbuffer.depth"), point)
        .storageBuffer(LPV_GRADIENT_SUM, graph.import(accum_))
        .storageBuffer(LPV_GRADIENT_KEPT_SUM, graph.import(keptAccum_))
        .uniform(LPV_GRADIENT_KEPT_CASCADES, graph.import(keptCascades_.current()))
        .storageImage(LPV_GRADIENT_CHANGE, change)
        .bytes(uint64_t(change_.width()) * change_.height() * blockBytes + accum_.size() + keptAccum_.size())
        .record([this, push = push_, groups](PassContext& c) { run(c, gradient_, push, groups); });
    graph.publish(names::kGiChangeImage, change);
}

void LightPropagationVolume::addGather(FrameGraph& graph) {
    const VkSampler point = pointSampler_.handle();
    const ImageHandle irradiance = graph.import(irradiance_);
    graph.publish("gi.irradiance", irradiance);
    gpu::LpvPush push = push_;
    push.sliceAxis = settings_.sliceAxis;
    push.sliceIndex = std::min(settings_.sliceIndex, settings_.resolution - 1);
    // Per pixel: depth and normal read, irradiance written; the summed volume read once.
    const uint64_t pixelBytes = texelBytesOf(graph, "gbuffer.depth") + texelBytesOf(graph, "gbuffer.normal") +
                                vk::texelBytes(irradiance_.format());
    graph.pass("lpv.gather")
        .pipeline(gather_.pipeline)
        .uniform(LPV_GATHER_FRAME, graph.buffer("frame"))
        .sampled(LPV_GATHER_GBUFFER_NORMAL, graph.image("gbuffer.normal"), point)
        .sampled(LPV_GATHER_GBUFFER_DEPTH, graph.image("gbuffer.depth"), point)
        .storageBuffer(LPV_GATHER_SUM, graph.import(accum_))
        .storageBuffer(LPV_GATHER_GEOMETRY, graph.import(geometry_))
        .storageImage(LPV_GATHER_IRRADIANCE, irradiance)
        .bytes(uint64_t(width_) * height_ * pixelBytes + accum_.size())
        .record([this, push](PassContext& c) { run(c, gather_, push, {vk::divUp(width_, 8), vk::divUp(height_, 8), 1}); });
}

}  // namespace penumbra
