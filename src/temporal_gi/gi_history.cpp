#include "temporal_gi/gi_history.h"

#include "core/names.h"
#include "core/previous_frame.h"
#include "shared/types.h"
#include "temporal_gi/bindings.h"
#include "vk/format_bytes.h"

namespace penumbra {
namespace {

constexpr VkFormat kColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;  // a long mean: half floats would stall it
constexpr VkFormat kMomentsFormat = VK_FORMAT_R32G32_SFLOAT;  // a squared irradiance outgrows half floats
constexpr VkFormat kGeometryFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

}  // namespace

GiHistory::GiHistory(vk::Allocator& alloc, uint32_t width, uint32_t height)
    : alloc_(alloc), width_(width), height_(height) {
    vk::Context& ctx = alloc.context();
    constexpr VkDescriptorType kTex = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    constexpr VkDescriptorType kImg = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    constexpr VkDescriptorType kBuf = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    kernel_ = vk::ComputeKernel(ctx, "temporal_gi/accumulate.comp",
                                {{GI_ACCUMULATE_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                 {GI_ACCUMULATE_CURRENT, kTex},
                                 {GI_ACCUMULATE_GBUFFER_DEPTH, kTex},
                                 {GI_ACCUMULATE_GBUFFER_NORMAL, kTex},
                                 {GI_ACCUMULATE_HISTORY_COLOR, kTex},
                                 {GI_ACCUMULATE_HISTORY_MOMENTS, kTex},
                                 {GI_ACCUMULATE_HISTORY_GEOMETRY, kTex},
                                 {GI_ACCUMULATE_OUT_COLOR, kImg},
                                 {GI_ACCUMULATE_OUT_MOMENTS, kImg},
                                 {GI_ACCUMULATE_OUT_GEOMETRY, kImg},
                                 {GI_ACCUMULATE_MOTION_FIRST, kTex},
                                 {GI_ACCUMULATE_MOTION_FIRST + 1, kBuf},
                                 {GI_ACCUMULATE_MOTION_FIRST + 2, kBuf},
                                 {GI_ACCUMULATE_CHANGE, kTex}},
                                sizeof(gpu::GiAccumulatePush));
    changeWeight_ = vk::ComputeKernel(ctx, "temporal_gi/change_weight.comp",
                                      {{GI_CHANGE_WEIGHT_CHANGE, kTex}, {GI_CHANGE_WEIGHT_OUTPUT, kImg}},
                                      sizeof(gpu::GiAccumulatePush));
    nearest_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});
}

void GiHistory::allocate() {
    const VkImageUsageFlags usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    for (int i = 0; i < 2; ++i) {
        color_[i] = vk::Image(alloc_, {kColorFormat, width_, height_, 1, usage, "gi-history-color"});
        moments_[i] = vk::Image(alloc_, {kMomentsFormat, width_, height_, 1, usage, "gi-history-moments"});
        geometry_[i] = vk::Image(alloc_, {kGeometryFormat, width_, height_, 1, usage, "gi-history-geometry"});
    }
    valid_ = false;
}

void GiHistory::release() {
    for (int i = 0; i < 2; ++i) color_[i] = {}, moments_[i] = {}, geometry_[i] = {};
    weights_ = {};
    valid_ = false;
}

uint64_t GiHistory::bytes(uint64_t width, uint64_t height) {
    return 2 * width * height *
           (vk::texelBytes(kColorFormat) + vk::texelBytes(kMomentsFormat) + vk::texelBytes(kGeometryFormat));
}

// The least weight per change texel that the measured change asks for (change_weight.comp).
ImageHandle GiHistory::addChangeWeight(FrameGraph& graph, const GiBlend& blend) {
    const vk::Image& change = graph.imageOf(blend.change);
    if (weights_.width() != change.width() || weights_.height() != change.height())
        weights_ = vk::Image(alloc_, {VK_FORMAT_R32_SFLOAT, change.width(), change.height(), 1,
                                      VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, "gi-change-weights"});
    const ImageHandle weights = graph.import(weights_);
    gpu::GiAccumulatePush push{};
    push.lagTolerance = blend.lagTolerance;
    graph.pass("gi.change-weight")
        .pipeline(changeWeight_.pipeline)
        .sampled(GI_CHANGE_WEIGHT_CHANGE, blend.change, nearest_.handle())
        .storageImage(GI_CHANGE_WEIGHT_OUTPUT, weights)
        .record([this, weights, push](PassContext& c) {
            changeWeight_.pipeline.push(c.cmd, push);
            const vk::Image& image = c.image(weights);
            vkCmdDispatch(c.cmd, vk::divUp(image.width(), 8), vk::divUp(image.height(), 8), 1);
        });
    return weights;
}

GiHistoryImages GiHistory::addTo(FrameGraph& graph, ImageHandle current, const GiBlend& blend) {
    if (!color_[0].handle()) allocate();
    const uint32_t write = next_, read = 1 - next_;
    const GiHistoryImages out{graph.import(color_[write]), graph.import(moments_[write]),
                              graph.import(geometry_[write])};
    const ImageHandle outGeometry = out.geometry;
    gpu::GiAccumulatePush push{};
    push.minWeight = blend.minWeight;
    push.changeWeight = blend.changeWeight;
    push.historyValid = valid_ ? 1u : 0u;
    push.changePixels = blend.change ? blend.changePixels : 0u;
    push.lagTolerance = blend.lagTolerance;
    const VkSampler nearest = nearest_.handle();
    const ImageHandle weights = blend.change ? addChangeWeight(graph, blend) : current;  // `current`: never read
    PassBuilder pass = graph.pass("gi.accumulate");
    declarePreviousFrameInputs(pass, GI_ACCUMULATE_MOTION_FIRST, nearest);
    pass.pipeline(kernel_.pipeline)
        .uniform(GI_ACCUMULATE_FRAME, graph.buffer(names::kFrame))
        .sampled(GI_ACCUMULATE_CURRENT, current, nearest)
        .sampled(GI_ACCUMULATE_GBUFFER_DEPTH, graph.image(names::kGbufferDepth), nearest)
        .sampled(GI_ACCUMULATE_GBUFFER_NORMAL, graph.image(names::kGbufferNormal), nearest)
        .sampled(GI_ACCUMULATE_HISTORY_COLOR, graph.import(color_[read]), nearest)
        .sampled(GI_ACCUMULATE_HISTORY_MOMENTS, graph.import(moments_[read]), nearest)
        .sampled(GI_ACCUMULATE_HISTORY_GEOMETRY, graph.import(geometry_[read]), nearest)
        .sampled(GI_ACCUMULATE_CHANGE, weights, nearest)
        .storageImage(GI_ACCUMULATE_OUT_COLOR, out.color)
        .storageImage(GI_ACCUMULATE_OUT_MOMENTS, out.moments)
        .storageImage(GI_ACCUMULATE_OUT_GEOMETRY, outGeometry)
        .record([this, out, push](PassContext& c) {
            kernel_.pipeline.push(c.cmd, push);
            const vk::Image& image = c.image(out.color);
            vkCmdDispatch(c.cmd, vk::divUp(image.width(), 8), vk::divUp(image.height(), 8), 1);
        });
    next_ = read;
    valid_ = true;
    return out;
}

}  // namespace penumbra
