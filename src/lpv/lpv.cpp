#include "lpv/lpv.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace penumbra {
namespace {

constexpr VkDescriptorType kTex = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kSsbo = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                           kUbo = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kImg = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
constexpr VkBufferUsageFlags kVolumeUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;

float maxExtent(const Bounds& b) {
    const glm::vec3 e = b.max - b.min;
    return std::max({e.x, e.y, e.z, 1e-3f});
}

}  // namespace

uint32_t automaticCascadeCount(const Bounds& scene) {
    // A room-sized scene fits one grid; a city needs resolution near the camera and reach far away.
    return glm::length(scene.max - scene.min) < 20.0f ? 1u : 3u;
}

std::vector<gpu::GpuLpvCascade> placeCascades(const Bounds& scene, const glm::vec3& eye, uint32_t count,
                                              uint32_t resolution) {
    std::vector<gpu::GpuLpvCascade> out;
    const float extent = maxExtent(scene) * 1.02f;
    if (count == 1) {  // one grid fit to the scene (a margin of half a cell all round)
        const float cell = extent / float(resolution - 1);
        out.push_back({glm::vec4(scene.center() - 0.5f * cell * float(resolution), cell)});
        return out;
    }
    // Nested around the eye; the outermost is twice the scene so that it covers the scene from
    // anywhere inside it. Origins snap to whole cells, so static light stays put as the camera moves.
    for (uint32_t k = 0; k < count; ++k) {
        const float cell = 2.0f * extent / float(resolution) / float(1u << (count - 1 - k));
        const glm::vec3 origin = glm::floor(eye / cell - 0.5f * float(resolution)) * cell;
        out.push_back({glm::vec4(origin, cell)});
    }
    return out;
}

LightPropagationVolume::LightPropagationVolume(vk::Allocator& alloc, uint32_t width, uint32_t height,
                                               const LpvSettings& settings, const Bounds& bounds)
    : alloc_(alloc), settings_(settings), bounds_(bounds), width_(width), height_(height) {
    cascadeCount_ = settings.cascades ? settings.cascades : automaticCascadeCount(bounds);
    if (cascadeCount_ > LPV_MAX_CASCADES) throw vk::VulkanError("LPV: at most 4 cascades");
    if (settings.rsmResolution % settings.vplResolution)
        throw vk::VulkanError(fmt::format("LPV: the RSM resolution ({}) must be a multiple of the VPL resolution ({})",
                                          settings.rsmResolution, settings.vplResolution));
    vk::Context& ctx = alloc.context();
    const uint32_t push = sizeof(gpu::LpvPush);
    downsample_ = vk::ComputeKernel(ctx, "lpv/downsample.comp", {kTex, kTex, kTex, kSsbo, kSsbo, kSsbo}, push);
    inject_ = vk::ComputeKernel(ctx, "lpv/inject.comp", {kSsbo, kSsbo, kSsbo}, push);
    injectCamera_ = vk::ComputeKernel(ctx, "lpv/inject_camera.comp", {kUbo, kTex, kTex, kSsbo}, push);
    propagate_ = vk::ComputeKernel(ctx, "lpv/propagate.comp", {kSsbo, kSsbo, kSsbo, kSsbo}, push);
    gather_ = vk::ComputeKernel(ctx, "lpv/gather.comp", {kUbo, kTex, kTex, kSsbo, kSsbo, kImg}, push);
    pointSampler_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});

    const VkDeviceSize cells = VkDeviceSize(settings.resolution) * settings.resolution * settings.resolution;
    const VkDeviceSize light = cells * cascadeCount_ * 3 * 16;
    volumeA_ = vk::Buffer(alloc, light, kVolumeUsage, false, "lpv-light-a");
    volumeB_ = vk::Buffer(alloc, light, kVolumeUsage, false, "lpv-light-b");
    accum_ = vk::Buffer(alloc, light, kVolumeUsage, false, "lpv-light-sum");
    geometry_ = vk::Buffer(alloc, cells * cascadeCount_ * 16, kVolumeUsage, false, "lpv-geometry");
    irradiance_ = vk::Image(alloc, {VK_FORMAT_R32G32B32A32_SFLOAT, width, height, 1,
                                    VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                        VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                    "lpv-irradiance"});
    push_.grid = {settings.resolution, cascadeCount_, 0, 0};
    push_.counts = {0, settings.rsmResolution, settings.vplResolution, 0};
    push_.params = {settings.occlusion ? 1.0f : 0.0f, settings.blendCells, float(settings.cameraGeometryStep), 0};
}

void LightPropagationVolume::update(const glm::vec3& eye) {
    std::vector<gpu::GpuLpvCascade> c = placeCascades(bounds_, eye, cascadeCount_, settings_.resolution);
    for (uint32_t k = 0; k < cascadeCount_; ++k) push_.cascades[k] = c[k];
}

void LightPropagationVolume::run(VkCommandBuffer cmd, vk::ComputeKernel& kernel, vk::DescriptorWrites& writes,
                                 const gpu::LpvPush& push, glm::uvec3 groups) {
    kernel.pipeline.bind(cmd);
    writes.push(alloc_.context(), cmd, kernel.pipeline);
    kernel.pipeline.push(cmd, push);
    vkCmdDispatch(cmd, groups.x, groups.y, groups.z);
}

void LightPropagationVolume::addTo(FrameGraph& graph, const vk::Buffer& frame, const vk::Buffer& lights,
                                   GBufferPass& g, RsmPass& rsm) {
    if (layers_ != rsm.layerCount()) {
        layers_ = rsm.layerCount();
        const uint32_t n = settings_.vplResolution;
        vpls_ = vk::Buffer(alloc_, VkDeviceSize(std::max(layers_, 1u)) * n * n * sizeof(gpu::GpuVpl),
                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, false, "lpv-vpls");
        push_.counts.x = layers_ * n * n;
        push_.counts.w = layers_;
    }
    if (layers_ > 0) addDownsample(graph, lights, rsm);
    addInjection(graph);
    addCameraGeometry(graph, frame, g);
    addPropagation(graph);
    addGather(graph, frame, g);
}

void LightPropagationVolume::setVpls(vk::CommandContext& cmd, const std::vector<gpu::GpuVpl>& vpls) {
    vpls_ = cmd.createDeviceBuffer(vpls.data(), vpls.size() * sizeof(gpu::GpuVpl),
                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "lpv-vpls");
    layers_ = 1;
    push_.counts.x = uint32_t(vpls.size());
}

void LightPropagationVolume::addPropagationFromVpls(FrameGraph& graph) {
    addInjection(graph);
    addPropagation(graph);
}

void LightPropagationVolume::addDownsample(FrameGraph& graph, const vk::Buffer& lights, RsmPass& rsm) {
    PassDesc pass{"lpv.downsample", PassKind::Compute, {}, {}, {}};
    pass.images = {{&rsm.depth(), Use::Sampled}, {&rsm.normal(), Use::Sampled}, {&rsm.flux(), Use::Sampled}};
    pass.buffers = {{&rsm.layerTable(), Use::StorageRead}, {&lights, Use::StorageRead}, {&vpls_, Use::StorageWrite}};
    // Each RSM texel read once (depth 4 + normal 4 + flux 8 bytes), each VPL written once.
    const uint64_t texels = uint64_t(settings_.rsmResolution) * settings_.rsmResolution * layers_;
    pass.bytes = texels * 16 + uint64_t(push_.counts.x) * sizeof(gpu::GpuVpl);
    pass.record = [this, &lights, &rsm, push = push_](VkCommandBuffer cmd) {
        const VkImageLayout depthRead = VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL;
        vk::DescriptorWrites w;
        w.sampled(0, rsm.depth().view(), pointSampler_.handle(), depthRead)
            .sampled(1, rsm.normal().view(), pointSampler_.handle())
            .sampled(2, rsm.flux().view(), pointSampler_.handle())
            .storageBuffer(3, rsm.layerTable())
            .storageBuffer(4, lights)
            .storageBuffer(5, vpls_);
        const uint32_t n = vk::divUp(settings_.vplResolution, 8);
        run(cmd, downsample_, w, push, {n, n, layers_});
    };
    graph.add(std::move(pass));
}

void LightPropagationVolume::addInjection(FrameGraph& graph) {
    PassDesc clear{"lpv.clear", PassKind::Transfer, {}, {}, {}};
    clear.bytes = volumeA_.size() + accum_.size() + geometry_.size();
    clear.buffers = {{&volumeA_, Use::TransferDst}, {&accum_, Use::TransferDst}, {&geometry_, Use::TransferDst}};
    clear.record = [this](VkCommandBuffer cmd) {
        for (const vk::Buffer* b : {&volumeA_, &accum_, &geometry_}) vkCmdFillBuffer(cmd, b->handle(), 0, VK_WHOLE_SIZE, 0);
    };
    graph.add(std::move(clear));
    if (layers_ > 0) {
        PassDesc inject{"lpv.inject", PassKind::Compute, {}, {}, {}};
        inject.buffers = {{&vpls_, Use::StorageRead}, {&volumeA_, Use::StorageWrite}, {&geometry_, Use::StorageWrite}};
        // Each VPL read once; per cascade 16 atomic read-modify-writes of 4 bytes.
        inject.bytes = uint64_t(push_.counts.x) * (sizeof(gpu::GpuVpl) + cascadeCount_ * 16 * 8);
        inject.record = [this, push = push_](VkCommandBuffer cmd) {
            vk::DescriptorWrites w;
            w.storageBuffer(0, vpls_).storageBuffer(1, volumeA_).storageBuffer(2, geometry_);
            run(cmd, inject_, w, push, {vk::divUp(push.counts.x, 64), 1, 1});
        };
        graph.add(std::move(inject));
    }
}

void LightPropagationVolume::addCameraGeometry(FrameGraph& graph, const vk::Buffer& frame, GBufferPass& g) {
    if (!settings_.cameraGeometry || !settings_.occlusion) return;
    PassDesc camera{"lpv.inject-camera", PassKind::Compute, {}, {}, {}};
    camera.images = {{&g.normal, Use::Sampled}, {&g.depth, Use::Sampled}};
    camera.buffers = {{&frame, Use::Uniform}, {&geometry_, Use::StorageWrite}};
    camera.record = [this, &frame, &g, push = push_](VkCommandBuffer cmd) {
        vk::DescriptorWrites w;
        w.uniformBuffer(0, frame)
            .sampled(1, g.normal.view(), pointSampler_.handle())
            .sampled(2, g.depth.view(), pointSampler_.handle(), VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL)
            .storageBuffer(3, geometry_);
        const uint32_t step = settings_.cameraGeometryStep;
        run(cmd, injectCamera_, w, push, {vk::divUp(vk::divUp(width_, step), 8), vk::divUp(vk::divUp(height_, step), 8), 1});
    };
    graph.add(std::move(camera));
}

void LightPropagationVolume::addPropagation(FrameGraph& graph) {
    const uint32_t r = settings_.resolution;
    for (uint32_t i = 0; i < settings_.iterations; ++i) {
        const vk::Buffer& src = i % 2 ? volumeB_ : volumeA_;
        const vk::Buffer& dst = i % 2 ? volumeA_ : volumeB_;
        PassDesc pass{fmt::format("lpv.propagate[{}]", i), PassKind::Compute, {}, {}, {}};
        pass.buffers = {{&src, Use::StorageRead}, {&dst, Use::StorageWrite}, {&accum_, Use::StorageWrite},
                        {&geometry_, Use::StorageRead}};
        gpu::LpvPush push = push_;
        push.grid.z = i == 0 ? 1u : 0u;
        // Per cell, once: source 48, geometry 16, destination 48, running sum read + written 96.
        pass.bytes = uint64_t(r) * r * r * cascadeCount_ * (48 + 16 + 48 + 96);
        pass.record = [this, &src, &dst, push, r](VkCommandBuffer cmd) {
            vk::DescriptorWrites w;
            w.storageBuffer(0, src).storageBuffer(1, dst).storageBuffer(2, accum_).storageBuffer(3, geometry_);
            run(cmd, propagate_, w, push, {vk::divUp(r, 4), vk::divUp(r, 4), vk::divUp(r * cascadeCount_, 4)});
        };
        graph.add(std::move(pass));
    }
}

void LightPropagationVolume::addGather(FrameGraph& graph, const vk::Buffer& frame, GBufferPass& g) {
    PassDesc pass{"lpv.gather", PassKind::Compute, {}, {}, {}};
    pass.images = {{&g.normal, Use::Sampled}, {&g.depth, Use::Sampled}, {&irradiance_, Use::StorageWrite}};
    pass.buffers = {{&frame, Use::Uniform}, {&accum_, Use::StorageRead}, {&geometry_, Use::StorageRead}};
    // Per pixel: depth 4 + normal 8 read, irradiance 16 written; the summed volume read once.
    pass.bytes = uint64_t(width_) * height_ * 28 + accum_.size();
    gpu::LpvPush push = push_;
    push.grid.z = settings_.sliceAxis;
    push.grid.w = std::min(settings_.sliceIndex, settings_.resolution - 1);
    pass.record = [this, &frame, &g, push](VkCommandBuffer cmd) {
        vk::DescriptorWrites w;
        w.uniformBuffer(0, frame)
            .sampled(1, g.normal.view(), pointSampler_.handle())
            .sampled(2, g.depth.view(), pointSampler_.handle(), VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL)
            .storageBuffer(3, accum_)
            .storageBuffer(4, geometry_)
            .storageImage(5, irradiance_.view());
        run(cmd, gather_, w, push, {vk::divUp(width_, 8), vk::divUp(height_, 8), 1});
    };
    graph.add(std::move(pass));
}

}  // namespace penumbra
