#include "rsm/rsm_gather.h"

#include <cmath>
#include <random>

namespace penumbra {
namespace {

constexpr VkFormat kIrradianceFormat = VK_FORMAT_R32G32B32A32_SFLOAT;  // exact sums stay exact

}  // namespace

std::vector<glm::vec4> rsmSamplePattern(const RsmSettings& s) {
    std::mt19937 rng(s.seed);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    const double texelsInDisc = M_PI * double(s.radius) * s.radius * double(s.resolution) * s.resolution;
    // E[xi1] = 1/2 and E[xi1^2] = 1/3: these factors make both weightings exact for a uniform field.
    const double norm = texelsInDisc / s.samples * (s.weights == RsmWeights::Unbiased ? 2.0 : 3.0);
    std::vector<glm::vec4> out(s.samples);
    for (glm::vec4& p : out) {
        const float xi1 = uniform(rng), xi2 = uniform(rng);
        const float angle = 2.0f * float(M_PI) * xi2;
        const float w = s.weights == RsmWeights::Unbiased ? xi1 : xi1 * xi1;
        p = {s.radius * xi1 * std::sin(angle), s.radius * xi1 * std::cos(angle), float(norm * w), 0.0f};
    }
    return out;
}

RsmGather::RsmGather(vk::Allocator& alloc, vk::CommandContext& cmd, uint32_t width, uint32_t height,
                     const RsmSettings& settings)
    : alloc_(alloc), cmd_(cmd), settings_(settings), width_(width), height_(height) {
    vk::Context& ctx = alloc.context();
    const VkDescriptorType ubo = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, tex = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                           ssbo = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, img = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    gather_ = vk::ComputeKernel(ctx, "rsm/gather.comp", {ubo, tex, tex, tex, tex, tex, ssbo, ssbo, img, ssbo},
                                sizeof(gpu::RsmPush));
    interpolate_ = vk::ComputeKernel(ctx, "rsm/interpolate.comp", {ubo, tex, tex, tex, img, ssbo}, sizeof(gpu::RsmPush));
    args_ = vk::ComputeKernel(ctx, "rsm/list_args.comp", {ssbo, ssbo}, 0);
    pointSampler_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});

    const uint32_t f = std::max(1u, settings.lowResFactor);
    lowWidth_ = vk::divUp(width, f);
    lowHeight_ = vk::divUp(height, f);
    const VkImageUsageFlags use = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                  VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    irradiance_ = vk::Image(alloc, {kIrradianceFormat, width, height, 1, use, "rsm-irradiance"});
    if (settings.mode == RsmMode::Interpolated) {
        low_ = vk::Image(alloc, {kIrradianceFormat, lowWidth_, lowHeight_, 1, use, "rsm-irradiance-low"});
        pixelList_ = vk::Buffer(alloc, 16 + 8 * VkDeviceSize(width) * height,
                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                    VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                false, "rsm-fallback-pixels");
        dispatchArgs_ = vk::Buffer(alloc, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                                   false, "rsm-fallback-args");
    } else {
        pixelList_ = vk::Buffer(alloc, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false, "rsm-unused-list");
    }
    std::vector<glm::vec4> pattern = rsmSamplePattern(settings);
    samples_ = cmd.createDeviceBuffer(pattern.data(), pattern.size() * sizeof(glm::vec4),
                                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "rsm-samples");
}

// Push constants shared by the gather and interpolation passes; sizes are the low-resolution grid's
// for RSM_GATHER_LOWRES (which the interpolation reads), the full image's otherwise.
gpu::RsmPush RsmGather::constants(uint32_t mode, uint32_t layers) const {
    const bool low = mode == RSM_GATHER_LOWRES;
    return {{mode, settings_.samples, layers, std::max(1u, settings_.lowResFactor)},
            {low ? lowWidth_ : width_, low ? lowHeight_ : height_, settings_.resolution, 0},
            {settings_.normalThreshold, settings_.distanceThreshold, settings_.radius, 0}};
}

PassDesc RsmGather::gatherPass(const char* name, uint32_t mode, vk::Image& out, const vk::Buffer& frame,
                               GBufferPass& g, RsmPass& rsm) {
    PassDesc pass;
    pass.name = name;
    pass.images = {{&g.normal, Use::Sampled}, {&g.depth, Use::Sampled}, {&rsm.depth(), Use::Sampled},
                   {&rsm.normal(), Use::Sampled}, {&rsm.flux(), Use::Sampled}, {&out, Use::StorageWrite}};
    pass.buffers = {{&frame, Use::Uniform}, {&rsm.layerTable(), Use::StorageRead}, {&samples_, Use::StorageRead}};
    if (mode == RSM_GATHER_LIST) {
        pass.buffers.push_back({&pixelList_, Use::StorageRead});
        pass.buffers.push_back({&dispatchArgs_, Use::IndirectArgs});
    }
    const gpu::RsmPush pc = constants(mode, rsm.layerCount());
    pass.record = [this, mode, pc, &out, &frame, &g, &rsm](VkCommandBuffer cmd) {
        gather_.pipeline.bind(cmd);
        const VkImageLayout depthRead = VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL;
        vk::DescriptorWrites()
            .uniformBuffer(0, frame)
            .sampled(1, g.normal.view(), pointSampler_.handle())
            .sampled(2, g.depth.view(), pointSampler_.handle(), depthRead)
            .sampled(3, rsm.depth().view(), pointSampler_.handle(), depthRead)
            .sampled(4, rsm.normal().view(), pointSampler_.handle())
            .sampled(5, rsm.flux().view(), pointSampler_.handle())
            .storageBuffer(6, rsm.layerTable())
            .storageBuffer(7, samples_)
            .storageImage(8, out.view())
            .storageBuffer(9, pixelList_)
            .push(alloc_.context(), cmd, gather_.pipeline);
        gather_.pipeline.push(cmd, pc);
        if (mode == RSM_GATHER_LIST) vkCmdDispatchIndirect(cmd, dispatchArgs_.handle(), 0);
        else vkCmdDispatch(cmd, vk::divUp(pc.sizes.x, 8), vk::divUp(pc.sizes.y, 8), 1);
    };
    return pass;
}

void RsmGather::addTo(FrameGraph& graph, const vk::Buffer& frame, GBufferPass& g, RsmPass& rsm) {
    if (settings_.mode == RsmMode::Full || settings_.mode == RsmMode::AllTexels) {
        const uint32_t mode = settings_.mode == RsmMode::Full ? RSM_GATHER_FULL : RSM_GATHER_ALL_TEXELS;
        graph.add(gatherPass("rsm.gather", mode, irradiance_, frame, g, rsm));
        return;
    }
    graph.add(gatherPass("rsm.gather-lowres", RSM_GATHER_LOWRES, low_, frame, g, rsm));

    PassDesc clear{"rsm.clear-list", PassKind::Transfer, {}, {{&pixelList_, Use::TransferDst}}, {}};
    clear.record = [this](VkCommandBuffer cmd) { vkCmdFillBuffer(cmd, pixelList_.handle(), 0, 16, 0); };
    graph.add(std::move(clear));

    PassDesc interp{"rsm.interpolate", PassKind::Compute, {}, {}, {}};
    interp.images = {{&g.normal, Use::Sampled}, {&g.depth, Use::Sampled}, {&low_, Use::Sampled},
                     {&irradiance_, Use::StorageWrite}};
    interp.buffers = {{&frame, Use::Uniform}, {&pixelList_, Use::StorageWrite}};
    const gpu::RsmPush pc = constants(RSM_GATHER_LOWRES, rsm.layerCount());  // sizes = the low-res grid
    interp.record = [this, pc, &frame, &g](VkCommandBuffer cmd) {
        interpolate_.pipeline.bind(cmd);
        vk::DescriptorWrites()
            .uniformBuffer(0, frame)
            .sampled(1, g.normal.view(), pointSampler_.handle())
            .sampled(2, g.depth.view(), pointSampler_.handle(), VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL)
            .sampled(3, low_.view(), pointSampler_.handle())
            .storageImage(4, irradiance_.view())
            .storageBuffer(5, pixelList_)
            .push(alloc_.context(), cmd, interpolate_.pipeline);
        interpolate_.pipeline.push(cmd, pc);
        vkCmdDispatch(cmd, vk::divUp(width_, 8), vk::divUp(height_, 8), 1);
    };
    graph.add(std::move(interp));

    PassDesc args{"rsm.fallback-args", PassKind::Compute, {}, {}, {}};
    args.buffers = {{&pixelList_, Use::StorageRead}, {&dispatchArgs_, Use::StorageWrite}};
    args.record = [this](VkCommandBuffer cmd) {
        args_.pipeline.bind(cmd);
        vk::DescriptorWrites().storageBuffer(0, pixelList_).storageBuffer(1, dispatchArgs_)
            .push(alloc_.context(), cmd, args_.pipeline);
        vkCmdDispatch(cmd, 1, 1, 1);
    };
    graph.add(std::move(args));
    graph.add(gatherPass("rsm.gather-fallback", RSM_GATHER_LIST, irradiance_, frame, g, rsm));
}

double RsmGather::fallbackFraction() {
    if (settings_.mode != RsmMode::Interpolated) return 0.0;
    std::vector<uint8_t> header = cmd_.readBuffer(pixelList_, 4);
    uint32_t count = 0;
    std::memcpy(&count, header.data(), 4);
    return double(count) / (double(width_) * height_);
}

}  // namespace penumbra
