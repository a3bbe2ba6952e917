#include "render/frame_graph.h"

#include <fmt/format.h>

namespace penumbra {
namespace {

struct Sync {
    VkImageLayout layout;
    VkPipelineStageFlags2 stage;
    VkAccessFlags2 access;
    bool writes;
};

VkPipelineStageFlags2 shaderStages(PassKind kind) {
    switch (kind) {
        case PassKind::Raster: return VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
        case PassKind::Compute: return VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
        default: return VK_PIPELINE_STAGE_2_COPY_BIT;
    }
}

Sync syncFor(Use use, PassKind kind, bool depthImage) {
    const VkPipelineStageFlags2 sh = shaderStages(kind);
    switch (use) {
        case Use::Sampled:
            return {depthImage ? VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, sh,
                    VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, false};
        case Use::StorageRead:
            return {VK_IMAGE_LAYOUT_GENERAL, sh, VK_ACCESS_2_SHADER_STORAGE_READ_BIT, false};
        case Use::StorageWrite:
            return {VK_IMAGE_LAYOUT_GENERAL, sh,
                    VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, true};
        case Use::ColorAttachment:
            return {VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, true};
        case Use::DepthAttachment:
            return {VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                    true};
        case Use::Uniform:
            return {VK_IMAGE_LAYOUT_UNDEFINED, sh, VK_ACCESS_2_UNIFORM_READ_BIT, false};
        case Use::VertexInput:
            return {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_VERTEX_INPUT_BIT,
                    VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_2_INDEX_READ_BIT, false};
        case Use::TransferSrc:
            return {VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                    VK_ACCESS_2_TRANSFER_READ_BIT, false};
        case Use::TransferDst:
            return {VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                    VK_ACCESS_2_TRANSFER_WRITE_BIT, true};
        case Use::IndirectArgs:
            return {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                    VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT, false};
    }
    return {};
}

constexpr VkAccessFlags2 kWriteAccess =
    VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT |
    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_HOST_WRITE_BIT;

const char* useName(Use u) {
    static const char* names[] = {"sampled", "storage-read", "storage-write", "color", "depth",
                                  "uniform", "vertex",       "transfer-src",  "transfer-dst", "indirect"};
    return names[static_cast<int>(u)];
}

}  // namespace

void FrameGraph::barriers(VkCommandBuffer cmd, const PassDesc& pass) {
    std::vector<VkImageMemoryBarrier2> imageBarriers;
    for (const ImageAccess& a : pass.images) {
        Sync s = syncFor(a.use, pass.kind, vk::isDepthFormat(a.image->format()));
        vk::ImageState& st = a.image->state();
        const bool hazard = s.writes || (st.access & kWriteAccess) || st.layout != s.layout;
        if (!hazard) {  // read after read in the same layout: just widen the reader set
            st.stage |= s.stage;
            st.access |= s.access;
            continue;
        }
        VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
        b.srcStageMask = st.stage ? st.stage : VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT;
        b.srcAccessMask = st.access & kWriteAccess;
        b.dstStageMask = s.stage;
        b.dstAccessMask = s.access;
        // Attachments are fully overwritten or cleared by their pass, except when loaded.
        b.oldLayout = st.layout;
        b.newLayout = s.layout;
        b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.image = a.image->handle();
        b.subresourceRange = a.image->fullRange();
        imageBarriers.push_back(b);
        st = {s.layout, s.stage, s.access};
    }
    VkMemoryBarrier2 mem{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    bool needMem = false;
    for (const BufferAccess& a : pass.buffers) {
        Sync s = syncFor(a.use, pass.kind, false);
        BufferState& st = bufferStates_[a.buffer->handle()];
        if (s.writes || (st.access & kWriteAccess)) {
            mem.srcStageMask |= st.stage ? st.stage : VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT;
            mem.srcAccessMask |= st.access & kWriteAccess;
            mem.dstStageMask |= s.stage;
            mem.dstAccessMask |= s.access;
            needMem = true;
            st = {s.stage, s.access};
        } else {
            st.stage |= s.stage;
            st.access |= s.access;
        }
    }
    if (imageBarriers.empty() && !needMem) return;
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.memoryBarrierCount = needMem ? 1 : 0;
    dep.pMemoryBarriers = &mem;
    dep.imageMemoryBarrierCount = static_cast<uint32_t>(imageBarriers.size());
    dep.pImageMemoryBarriers = imageBarriers.data();
    vkCmdPipelineBarrier2(cmd, &dep);
}

void FrameGraph::execute(VkCommandBuffer cmd, vk::GpuTimer* timer) {
    bufferStates_.clear();
    for (const PassDesc& pass : passes_) {
        barriers(cmd, pass);
        uint32_t scope = timer ? timer->begin(cmd, pass.name) : 0;
        pass.record(cmd);
        if (timer) timer->end(cmd, scope);
    }
}

std::string FrameGraph::describe() const {
    std::string out;
    for (const PassDesc& p : passes_) {
        std::vector<std::string> reads, writes;
        auto sort = [&](const std::string& name, Use u) {
            Sync s = syncFor(u, p.kind, false);
            (s.writes ? writes : reads).push_back(fmt::format("{}({})", name, useName(u)));
        };
        for (const ImageAccess& a : p.images) sort(a.image->name(), a.use);
        for (const BufferAccess& a : p.buffers) sort(a.buffer->name(), a.use);
        out += fmt::format("{:<22} {:<8} reads [{}] writes [{}]\n", p.name,
                           p.kind == PassKind::Raster ? "raster" : p.kind == PassKind::Compute ? "compute" : "copy",
                           fmt::join(reads, ", "), fmt::join(writes, ", "));
    }
    return out;
}

}  // namespace penumbra
