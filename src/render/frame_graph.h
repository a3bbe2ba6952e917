// An explicit pass list: each pass declares the images and buffers it reads and writes; the graph
// inserts the barriers between passes and wraps each pass in a GPU timestamp scope.
// Techniques plug in by adding passes (see Renderer::buildFrame for the order).
#pragma once
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

#include "vk/commands.h"
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

struct ImageAccess {
    vk::Image* image;
    Use use;
};

struct BufferAccess {
    const vk::Buffer* buffer;
    Use use;
};

struct PassDesc {
    std::string name;
    PassKind kind = PassKind::Compute;
    std::vector<ImageAccess> images;
    std::vector<BufferAccess> buffers;
    std::function<void(VkCommandBuffer)> record;
    // Bytes the pass must move at the least (reads + writes of its data, once), for passes bound by
    // memory bandwidth; `penumbra bench` reports the achieved GB/s against the copy bandwidth. 0 = n/a.
    uint64_t bytes = 0;
};

class FrameGraph {
public:
    void add(PassDesc pass) { passes_.push_back(std::move(pass)); }
    void clear() { passes_.clear(); }
    // Records every pass in order with barriers and (when `timer` is set) one timestamp scope each.
    void execute(VkCommandBuffer cmd, vk::GpuTimer* timer);
    const std::vector<PassDesc>& passes() const { return passes_; }
    // One line per pass: name, kind, what it reads and writes (for `--print-passes` and the docs).
    std::string describe() const;

private:
    struct BufferState {
        VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_NONE;
        VkAccessFlags2 access = VK_ACCESS_2_NONE;
    };
    void barriers(VkCommandBuffer cmd, const PassDesc& pass);
    std::vector<PassDesc> passes_;
    std::unordered_map<VkBuffer, BufferState> bufferStates_;
};

}  // namespace penumbra
