#include "core/frame_graph.h"

#include <algorithm>

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

VkImageLayout sampledLayout(const vk::Image& image) {
    return vk::isDepthFormat(image.format()) ? VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL
                                             : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
}

const char* useName(Use u) {
    static const char* names[] = {"sampled", "storage-read", "storage-write", "color", "depth",
                                  "uniform", "vertex",       "transfer-src",  "transfer-dst", "indirect"};
    return names[static_cast<int>(u)];
}

// "a, a, a, b" -> "a x3, b".
void collapseRepeats(std::vector<std::string>& names) {
    std::vector<std::string> out;
    for (size_t i = 0, j; i < names.size(); i = j) {
        for (j = i + 1; j < names.size() && names[j] == names[i];) ++j;
        out.push_back(j - i > 1 ? fmt::format("{} x{}", names[i], j - i) : names[i]);
    }
    names = std::move(out);
}

}  // namespace

// One barrier for a whole group: each resource's uses by the group's passes merged (schedule() puts
// no two passes in a group that write the same resource, or read it in different layouts).
void FrameGraph::barriers(VkCommandBuffer cmd, const std::vector<uint32_t>& group) {
    std::vector<std::pair<vk::Image*, Sync>> imageUses;
    std::vector<std::pair<VkBuffer, Sync>> uses;
    auto merge = [](auto& list, auto key, const Sync& s) {
        auto same = std::find_if(list.begin(), list.end(), [key](const auto& u) { return u.first == key; });
        if (same == list.end()) return list.emplace_back(key, s), void();
        same->second.stage |= s.stage;
        same->second.access |= s.access;
        same->second.writes |= s.writes;
    };
    for (uint32_t p : group) {
        const PassDesc& pass = passes_[p];
        for (const auto& [handle, use] : pass.images) {
            vk::Image& image = imageOf(handle);
            merge(imageUses, &image, syncFor(use, pass.kind, vk::isDepthFormat(image.format())));
        }
        // A buffer used more than once (storage and indirect arguments) waits once, for all its uses.
        for (const auto& [handle, use] : pass.buffers) merge(uses, bufferOf(handle).handle(), syncFor(use, pass.kind, false));
    }
    std::vector<VkImageMemoryBarrier2> imageBarriers;
    for (auto& [imagePtr, s] : imageUses) {
        vk::Image& image = *imagePtr;
        vk::ImageState& st = image.state();
        const bool hazard = s.writes || (st.access & kWriteAccess) || st.layout != s.layout;
        // A reader in a stage the last transition was not made visible to (a raster pass sampled the
        // image first, a compute pass samples it next) needs an execution dependency on the readers
        // before it, which chains it after that transition; the reader set only widens.
        const bool newStage = (s.stage & ~st.stage) != 0;
        if (!hazard && !newStage) {  // read after read in the same layout and stages: nothing to wait for
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
        b.image = image.handle();
        b.subresourceRange = image.fullRange();
        if (!hazard) {  // execution dependency only: same layout, nothing written
            b.srcAccessMask = VK_ACCESS_2_NONE;
            imageBarriers.push_back(b);
            st.stage |= s.stage;
            st.access |= s.access;
            continue;
        }
        imageBarriers.push_back(b);
        st = {s.layout, s.stage, s.access};
    }
    VkMemoryBarrier2 mem{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    bool needMem = false;
    for (const auto& [buffer, s] : uses) {
        BufferState& st = bufferStates_[buffer];
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

// Binds the pass's pipeline, pushes its set 0, made only from the pass's declarations, and binds the
// long-lived sets it declared.
void FrameGraph::bind(VkCommandBuffer cmd, const PassDesc& pass) {
    if (!pass.pipeline) return;
    pass.pipeline->bind(cmd);
    for (const auto& [index, set] : pass.sets)
        vkCmdBindDescriptorSets(cmd, pass.pipeline->bindPoint(), pass.pipeline->layout(), index, 1, &set, 0, nullptr);
    if (pass.bindings.empty()) return;
    vk::DescriptorWrites writes;
    for (const PassBinding& b : pass.bindings) {
        switch (b.type) {
            case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER: {
                const vk::Image& image = imageOf(b.image);
                writes.sampled(b.binding, image.view(), b.sampler, sampledLayout(image));
                break;
            }
            case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE: writes.storageImage(b.binding, imageOf(b.image).view()); break;
            case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER: writes.storageBuffer(b.binding, bufferOf(b.buffer)); break;
            case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER: writes.uniformBuffer(b.binding, bufferOf(b.buffer)); break;
            default: throw vk::VulkanError("frame graph: unsupported descriptor type in pass " + pass.name);
        }
    }
    writes.push(ctx_, cmd, *pass.pipeline);
}

void FrameGraph::execute(VkCommandBuffer cmd, vk::GpuTimer* timer) {
    if (!passTimings_) timer = nullptr;
    for (const std::vector<uint32_t>& group : schedule()) {
        barriers(cmd, group);
        for (uint32_t i : group) {
            const PassDesc& pass = passes_[i];
            ctx_.debugUtils().beginLabel(cmd, pass.name.c_str());
            uint32_t scope = timer ? timer->begin(cmd, pass.name) : 0;
            bind(cmd, pass);
            PassContext context(cmd, *this, i);
            if (pass.record) pass.record(context);
            if (timer) timer->end(cmd, scope);
            ctx_.debugUtils().endLabel(cmd);
        }
    }
}

std::vector<std::vector<uint32_t>> FrameGraph::schedule(bool overlap) const {
    std::vector<std::vector<uint32_t>> groups;
    if (!overlap) {
        for (uint32_t i = 0; i < passes_.size(); ++i) groups.push_back({i});
        return groups;
    }
    // Per resource, in the order passes were added: its last writer (or layout change) and the
    // readers since. A pass's level is one more than the highest of the passes it must follow.
    struct Access {
        int writer = -1;
        std::vector<uint32_t> readers;
        VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    };
    std::unordered_map<const vk::Image*, Access> imageAccesses;
    std::unordered_map<VkBuffer, Access> bufferAccesses;
    std::vector<uint32_t> level(passes_.size(), 0);
    for (uint32_t j = 0; j < passes_.size(); ++j) {
        const PassDesc& pass = passes_[j];
        uint32_t lv = 0;
        auto follow = [&](int i) {
            if (i >= 0 && uint32_t(i) != j) lv = std::max(lv, level[i] + 1);
        };
        auto access = [&](Access& a, const Sync& s, bool image) {
            follow(a.writer);
            // A layout change is a write: it must wait for the readers of the old layout.
            const bool modifies = s.writes || (image && !a.readers.empty() && a.layout != s.layout);
            if (modifies) {
                for (uint32_t r : a.readers) follow(int(r));
                a.writer = int(j);
                a.readers.clear();
            } else if (a.readers.empty() || a.readers.back() != j) {
                a.readers.push_back(j);
            }
            a.layout = s.layout;
        };
        for (const auto& [h, use] : pass.images)
            access(imageAccesses[&imageOf(h)], syncFor(use, pass.kind, vk::isDepthFormat(imageOf(h).format())), true);
        for (const auto& [h, use] : pass.buffers)
            access(bufferAccesses[bufferOf(h).handle()], syncFor(use, pass.kind, false), false);
        level[j] = lv;
        if (groups.size() <= lv) groups.resize(lv + 1);
        groups[lv].push_back(j);
    }
    return groups;
}

void FrameGraph::clear() {
    passes_.clear();
    images_.clear();
    buffers_.clear();
    indexOf_.clear();
    imageNames_.clear();
    bufferNames_.clear();
    contributions_.clear();
}

ImageHandle FrameGraph::import(vk::Image& image) {
    auto [it, added] = indexOf_.emplace(&image, uint32_t(images_.size()));
    if (added) images_.push_back(&image);
    return ImageHandle{it->second};
}

BufferHandle FrameGraph::import(const vk::Buffer& buffer) {
    auto [it, added] = indexOf_.emplace(&buffer, uint32_t(buffers_.size()));
    if (added) buffers_.push_back(&buffer);
    return BufferHandle{it->second};
}

// A capture tool shows a published resource under its published name.
void FrameGraph::publish(const std::string& name, ImageHandle image) {
    imageNames_[name] = image;
    ctx_.debugUtils().name(VK_OBJECT_TYPE_IMAGE, imageOf(image).handle(), name.c_str());
}

void FrameGraph::publish(const std::string& name, BufferHandle buffer) {
    bufferNames_[name] = buffer;
    ctx_.debugUtils().name(VK_OBJECT_TYPE_BUFFER, bufferOf(buffer).handle(), name.c_str());
}

ImageHandle FrameGraph::image(const std::string& name) const {
    auto it = imageNames_.find(name);
    if (it == imageNames_.end()) throw vk::VulkanError("frame graph: no image published as '" + name + "'");
    return it->second;
}

BufferHandle FrameGraph::buffer(const std::string& name) const {
    auto it = bufferNames_.find(name);
    if (it == bufferNames_.end()) throw vk::VulkanError("frame graph: no buffer published as '" + name + "'");
    return it->second;
}

vk::Image& PassContext::image(ImageHandle h) const {
    for (const auto& [declared, use] : graph_.passes_[pass_].images)
        if (declared.index == h.index) return graph_.imageOf(h);
    throw vk::VulkanError("frame graph: pass " + graph_.passes_[pass_].name + " uses an image it did not declare");
}

const vk::Buffer& PassContext::buffer(BufferHandle h) const {
    for (const auto& [declared, use] : graph_.passes_[pass_].buffers)
        if (declared.index == h.index) return graph_.bufferOf(h);
    throw vk::VulkanError("frame graph: pass " + graph_.passes_[pass_].name + " uses a buffer it did not declare");
}

PassBuilder::PassBuilder(FrameGraph& g, std::string name, PassKind kind) : graph_(g) {
    pass_.name = std::move(name);
    pass_.kind = kind;
}

PassBuilder& PassBuilder::pipeline(const vk::Pipeline& p) {
    pass_.pipeline = &p;
    return *this;
}

PassBuilder& PassBuilder::sampled(uint32_t binding, ImageHandle image, VkSampler sampler) {
    pass_.images.push_back({image, Use::Sampled});
    pass_.bindings.push_back({binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, image, {}, sampler});
    return *this;
}

PassBuilder& PassBuilder::storageImage(uint32_t binding, ImageHandle image, Use use) {
    pass_.images.push_back({image, use});
    pass_.bindings.push_back({binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, image, {}, VK_NULL_HANDLE});
    return *this;
}

PassBuilder& PassBuilder::storageBuffer(uint32_t binding, BufferHandle buffer, Use use) {
    pass_.buffers.push_back({buffer, use});
    pass_.bindings.push_back({binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, {}, buffer, VK_NULL_HANDLE});
    return *this;
}

PassBuilder& PassBuilder::uniform(uint32_t binding, BufferHandle buffer) {
    pass_.buffers.push_back({buffer, Use::Uniform});
    pass_.bindings.push_back({binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, {}, buffer, VK_NULL_HANDLE});
    return *this;
}

PassBuilder& PassBuilder::descriptorSet(uint32_t set, VkDescriptorSet handle, const std::vector<ImageHandle>& sampled) {
    for (ImageHandle image : sampled) pass_.images.push_back({image, Use::Sampled});
    pass_.sets.push_back({set, handle});
    return *this;
}

PassBuilder& PassBuilder::use(ImageHandle image, Use use) {
    pass_.images.push_back({image, use});
    return *this;
}

PassBuilder& PassBuilder::use(BufferHandle buffer, Use use) {
    pass_.buffers.push_back({buffer, use});
    return *this;
}

PassBuilder& PassBuilder::bytes(uint64_t moved) {
    pass_.bytes = moved;
    return *this;
}

void PassBuilder::record(std::function<void(PassContext&)> fn) {
    pass_.record = std::move(fn);
    graph_.add(std::move(pass_));
}

std::string FrameGraph::describe() const {
    std::vector<uint32_t> groupOf(passes_.size());
    const std::vector<std::vector<uint32_t>> groups = schedule(true);
    for (uint32_t g = 0; g < groups.size(); ++g)
        for (uint32_t i : groups[g]) groupOf[i] = g;
    std::string out;
    for (uint32_t i = 0; i < passes_.size(); ++i) {
        const PassDesc& p = passes_[i];
        std::vector<std::string> reads, writes;
        auto sort = [&](const std::string& name, Use u) {
            Sync s = syncFor(u, p.kind, false);
            (s.writes ? writes : reads).push_back(fmt::format("{}({})", name, useName(u)));
        };
        for (const auto& [h, use] : p.images) sort(imageOf(h).name(), use);
        for (const auto& [h, use] : p.buffers) sort(bufferOf(h).name(), use);
        collapseRepeats(reads);  // a texture table is many images of one name
        out += fmt::format("{:<22} group {:<3} {:<8} reads [{}] writes [{}]\n", p.name, groupOf[i],
                           p.kind == PassKind::Raster ? "raster" : p.kind == PassKind::Compute ? "compute" : "copy",
                           fmt::join(reads, ", "), fmt::join(writes, ", "));
    }
    return out;
}

}  // namespace penumbra
