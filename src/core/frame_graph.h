// The frame graph: passes declare every image and buffer they touch, by handle, and the graph binds
// the descriptor set of each pass from those declarations (push descriptors; long-lived tables such as the
// material textures are bound as declared sets), inserts the barriers
// between passes (and across frames: resource states persist), and wraps each pass in a GPU
// timestamp scope. A pass cannot bind what it did not declare: descriptor pushes exist only here.
//
// Resources enter a frame with import() and get a handle; techniques publish their outputs by name
// (publish("shadow.mask", h)) and read other techniques' outputs the same way (image("shadow.mask")),
// so the lighting pass knows names, not technique classes. See Renderer::recordFrame for the order.
#pragma once
#include <functional>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/blackboard.h"
#include "vk/commands.h"
#include "vk/pipeline.h"
#include "vk/timestamps.h"

namespace penumbra {

enum class PassKind { Raster, Compute, Transfer };

enum class Use {
    Sampled,          // texture / texelFetch read
    StorageRead,      // storage image or storage buffer read
    StorageWrite,     // storage image or storage buffer write (read-modify-write included)
    ColorAttachment,
    DepthAttachment,  // depth test and write
    Uniform,
    VertexInput,      // vertex or index buffer
    TransferSrc,
    TransferDst,
    IndirectArgs,     // indirect dispatch or draw arguments
};

// Typed handles into the graph's resource table, valid while the frame is being built and run.
struct ImageHandle {
    uint32_t index = UINT32_MAX;
    explicit operator bool() const { return index != UINT32_MAX; }
};
struct BufferHandle {
    uint32_t index = UINT32_MAX;
    explicit operator bool() const { return index != UINT32_MAX; }
};

// One descriptor of a pass's set 0, made from a declaration.
struct PassBinding {
    uint32_t binding;
    VkDescriptorType type;
    ImageHandle image;
    BufferHandle buffer;
    VkSampler sampler = VK_NULL_HANDLE;
};

class FrameGraph;

// What a pass's record function may touch: the command buffer and its declared resources.
class PassContext {
public:
    VkCommandBuffer cmd;
    vk::Image& image(ImageHandle h) const;           // throws unless the pass declared h
    const vk::Buffer& buffer(BufferHandle h) const;  // throws unless the pass declared h

private:
    friend class FrameGraph;
    PassContext(VkCommandBuffer c, FrameGraph& g, uint32_t pass) : cmd(c), graph_(g), pass_(pass) {}
    FrameGraph& graph_;
    uint32_t pass_;
};

struct PassDesc {
    std::string name;
    PassKind kind = PassKind::Compute;
    const vk::Pipeline* pipeline = nullptr;  // bound, with set 0 pushed from `bindings`, before record
    std::vector<std::pair<ImageHandle, Use>> images;
    std::vector<std::pair<BufferHandle, Use>> buffers;
    std::vector<PassBinding> bindings;
    std::vector<std::pair<uint32_t, VkDescriptorSet>> sets;  // long-lived sets bound at sets 1..
    std::function<void(PassContext&)> record;
    // Bytes the pass must move at the least (reads + writes of its data, once), for passes bound by
    // memory bandwidth; `penumbra bench` reports the achieved GB/s against the copy bandwidth. 0 = n/a.
    uint64_t bytes = 0;
};

// Declares one pass: every call both declares the access (for barriers) and, for the descriptor
// forms, binds it at `binding` of set 0 of the pass's pipeline.
class PassBuilder {
public:
    PassBuilder& pipeline(const vk::Pipeline& p);
    PassBuilder& sampled(uint32_t binding, ImageHandle image, VkSampler sampler);
    PassBuilder& storageImage(uint32_t binding, ImageHandle image, Use use = Use::StorageWrite);
    PassBuilder& storageBuffer(uint32_t binding, BufferHandle buffer, Use use = Use::StorageRead);
    PassBuilder& uniform(uint32_t binding, BufferHandle buffer);
    // A long-lived descriptor set (vk::DescriptorSet) bound at `set`, whose images the pass samples.
    PassBuilder& descriptorSet(uint32_t set, VkDescriptorSet handle, const std::vector<ImageHandle>& sampled);
    // Accesses without a descriptor: attachments, indirect arguments, transfers, vertex input.
    PassBuilder& use(ImageHandle image, Use use);
    PassBuilder& use(BufferHandle buffer, Use use);
    PassBuilder& bytes(uint64_t moved);
    // Adds the pass to the graph.
    void record(std::function<void(PassContext&)> fn);
    FrameGraph& graph() { return graph_; }

private:
    friend class FrameGraph;
    PassBuilder(FrameGraph& g, std::string name, PassKind kind);
    FrameGraph& graph_;
    PassDesc pass_;
};

class FrameGraph {
public:
    explicit FrameGraph(vk::Context& ctx) : ctx_(ctx) {}
    // Registers a resource for this frame (the same object twice gives the same handle).
    ImageHandle import(vk::Image& image);
    BufferHandle import(const vk::Buffer& buffer);
    // The blackboard: outputs by name. Reading a name nobody published throws.
    void publish(const std::string& name, ImageHandle image);
    void publish(const std::string& name, BufferHandle buffer);
    ImageHandle image(const std::string& name) const;
    BufferHandle buffer(const std::string& name) const;
    bool hasImage(const std::string& name) const { return imageNames_.count(name) > 0; }
    bool hasBuffer(const std::string& name) const { return bufferNames_.count(name) > 0; }
    // The same by typed name (core/names.h).
    void publish(ImageName name, ImageHandle image) { publish(std::string(name.id), image); }
    void publish(BufferName name, BufferHandle buffer) { publish(std::string(name.id), buffer); }
    ImageHandle image(ImageName name) const { return image(std::string(name.id)); }
    BufferHandle buffer(BufferName name) const { return buffer(std::string(name.id)); }
    bool has(ImageName name) const { return hasImage(name.id); }
    bool has(BufferName name) const { return hasBuffer(name.id); }
    // Names that any number of passes publish under, each adding one image (the indirect irradiance
    // contributions): the reader takes the list, in the order contributed.
    void contribute(ImageName name, ImageHandle image) { contributions_[name.id].push_back(image); }
    std::vector<ImageHandle> contributions(ImageName name) const {
        const auto it = contributions_.find(name.id);
        return it == contributions_.end() ? std::vector<ImageHandle>{} : it->second;
    }
    // Replaces the list (a pass that folded the contributions into one image).
    void setContributions(ImageName name, std::vector<ImageHandle> images) {
        contributions_[name.id] = std::move(images);
    }

    PassBuilder pass(std::string name, PassKind kind = PassKind::Compute) {
        return PassBuilder(*this, std::move(name), kind);
    }
    void add(PassDesc pass) { passes_.push_back(std::move(pass)); }
    // Forgets the frame's passes, handles and names (resource states are kept: they span frames).
    void clear();
    // After resources were destroyed and re-created: forget their last uses too.
    void forgetStates() { bufferStates_.clear(); }
    // Records every pass with barriers and (when `timer` is set and pass timings are on) one timestamp
    // scope each, in the groups of schedule().
    void execute(VkCommandBuffer cmd, vk::GpuTimer* timer);
    // Groups of passes that run together: a pass's group comes after the groups of every pass it
    // depends on (it reads what they write, writes what they read or write, or needs an image in
    // another layout), and within a group passes keep their order. One barrier goes before each
    // group, none between its passes, so that independent work (the camera's lists, the light's)
    // overlaps on the GPU instead of each pass waiting for the one before. With overlap off, every
    // pass is a group of its own, in the order added.
    std::vector<std::vector<uint32_t>> schedule() const { return schedule(overlap_); }
    void setOverlap(bool on) { overlap_ = on; }
    // Off: no timestamps between passes (the frame's own scope only): a timestamp may wait for the
    // work before it, which would undo the overlap.
    void setPassTimings(bool on) { passTimings_ = on; }
    const std::vector<PassDesc>& passes() const { return passes_; }
    vk::Image& imageOf(ImageHandle h) const { return *images_.at(h.index); }
    const vk::Buffer& bufferOf(BufferHandle h) const { return *buffers_.at(h.index); }
    // One line per pass: name, the group it joins when passes overlap (whether or not they do now: pass
    // scopes run them in order), kind, what it reads and writes (`--print-passes`, the docs).
    std::string describe() const;

private:
    friend class PassContext;
    struct BufferState {
        VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_NONE;
        VkAccessFlags2 access = VK_ACCESS_2_NONE;
    };
    void barriers(VkCommandBuffer cmd, const std::vector<uint32_t>& group);
    std::vector<std::vector<uint32_t>> schedule(bool overlap) const;
    void bind(VkCommandBuffer cmd, const PassDesc& pass);
    vk::Context& ctx_;
    std::vector<PassDesc> passes_;
    std::vector<vk::Image*> images_;
    std::vector<const vk::Buffer*> buffers_;
    std::unordered_map<const void*, uint32_t> indexOf_;
    std::map<std::string, ImageHandle> imageNames_;
    std::map<std::string, BufferHandle> bufferNames_;
    std::map<std::string, std::vector<ImageHandle>> contributions_;
    std::unordered_map<VkBuffer, BufferState> bufferStates_;
    bool overlap_ = true, passTimings_ = true;
};

}  // namespace penumbra
