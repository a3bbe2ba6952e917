// Descriptor-set layouts, push-descriptor writes, compute and graphics pipelines.
// Passes bind their per-frame resources with push descriptors (VK_KHR_push_descriptor): no pools,
// no set lifetime to manage; only long-lived tables (material textures) use a pooled set (DescriptorSet).
#pragma once
#include <deque>
#include <string>
#include <vector>

#include "vk/resources.h"

namespace penumbra {
class FrameGraph;
}

namespace penumbra::vk {

struct Binding {
    uint32_t binding;
    VkDescriptorType type;
    uint32_t count = 1;
};

// What the C++ side declared for one pipeline: its shaders (keys of the embedded SPIR-V), the
// bindings of each descriptor set (set 0 first) and the push-constant bytes. Recorded when the
// pipeline is created; a test reflects the SPIR-V and compares (tests/spirv_reflection_test.cpp).
struct PipelineInterface {
    std::vector<std::string> shaders;
    std::vector<std::vector<Binding>> sets;
    uint32_t pushBytes = 0;
};
const std::vector<PipelineInterface>& declaredInterfaces(Context& ctx);

class DescriptorLayout {
public:
    DescriptorLayout() = default;
    DescriptorLayout(Context& ctx, const std::vector<Binding>& bindings, bool pushDescriptor = true);
    ~DescriptorLayout() { reset(); }
    DescriptorLayout(DescriptorLayout&& o) noexcept { *this = std::move(o); }
    DescriptorLayout& operator=(DescriptorLayout&& o) noexcept;
    VkDescriptorSetLayout handle() const { return layout_; }
    void reset();

private:
    VkDevice device_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout layout_ = VK_NULL_HANDLE;  // owned by the device's PipelineCache
};

struct GraphicsDesc {
    std::string vertexShader;
    std::string fragmentShader;  // empty: depth-only
    std::vector<VkFormat> colorFormats;
    VkFormat depthFormat = VK_FORMAT_UNDEFINED;
    uint32_t vertexStride = 0;     // 0: no vertex buffer (vertex pulling or generated)
    std::vector<VkVertexInputAttributeDescription> vertexAttributes;  // all from binding 0
    VkCullModeFlags cullMode = VK_CULL_MODE_NONE;
    bool dynamicCullMode = false;  // set per draw with vkCmdSetCullMode
    VkFrontFace frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    bool depthBias = false;        // set with vkCmdSetDepthBias
    bool depthClamp = false;
    VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;  // hair ribbons draw strips
    // Tessellation (both or neither): the draws' triangles become patches of 3 control points.
    std::string tessControlShader, tessEvalShader;
};

class Pipeline {
public:
    Pipeline() = default;
    static Pipeline compute(Context& ctx, const std::string& shader, const std::vector<VkDescriptorSetLayout>& sets,
                            uint32_t pushBytes);
    static Pipeline graphics(Context& ctx, const GraphicsDesc& desc, const std::vector<VkDescriptorSetLayout>& sets,
                             uint32_t pushBytes);
    ~Pipeline() { reset(); }
    Pipeline(Pipeline&& o) noexcept { *this = std::move(o); }
    Pipeline& operator=(Pipeline&& o) noexcept;

    VkPipeline handle() const { return pipeline_; }
    VkPipelineLayout layout() const { return layout_; }
    VkPipelineBindPoint bindPoint() const { return bindPoint_; }
    void bind(VkCommandBuffer cmd) const { vkCmdBindPipeline(cmd, bindPoint_, pipeline_); }
    void pushConstants(VkCommandBuffer cmd, const void* data, uint32_t bytes) const;
    template <class T> void push(VkCommandBuffer cmd, const T& value) const { pushConstants(cmd, &value, sizeof(T)); }
    void reset();

private:
    void createLayout(Context& ctx, const std::vector<VkDescriptorSetLayout>& sets, uint32_t pushBytes);
    bool fromCache(Context& ctx, const std::string& key);
    void addToCache(Context& ctx, const std::string& key);
    VkDevice device_ = VK_NULL_HANDLE;
    Context* ctx_ = nullptr;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipelineBindPoint bindPoint_ = VK_PIPELINE_BIND_POINT_COMPUTE;
};

// A compute shader with its push-descriptor layout: binding i has descriptor type types[i].
struct ComputeKernel {
    DescriptorLayout layout;
    Pipeline pipeline;
    ComputeKernel() = default;
    // Bindings given by number (a kernel that reads the scene's draw set, whose instance table sits at
    // SCENE_INSTANCES_BINDING).
    // `moreSets`: the layouts of sets 1.. (long-lived tables, see DescriptorSet).
    ComputeKernel(Context& ctx, const std::string& shader, const std::vector<Binding>& bindings, uint32_t pushBytes,
                  const std::vector<VkDescriptorSetLayout>& moreSets = {});
    ComputeKernel(Context& ctx, const std::string& shader, const std::vector<VkDescriptorType>& types,
                  uint32_t pushBytes);
};

// Collects descriptor writes for one push-descriptor set, then pushes them.
class DescriptorWrites {
public:
    DescriptorWrites() = default;
    // Writes point into this object's own storage: movable (deque/vector moves keep addresses), not copyable.
    DescriptorWrites(const DescriptorWrites&) = delete;
    DescriptorWrites(DescriptorWrites&&) = default;
    DescriptorWrites& sampled(uint32_t binding, VkImageView view, VkSampler sampler,
                              VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    DescriptorWrites& storageImage(uint32_t binding, VkImageView view);
    DescriptorWrites& storageBuffer(uint32_t binding, const Buffer& buffer);
    DescriptorWrites& uniformBuffer(uint32_t binding, const Buffer& buffer);
    // Element `element` of an array of sampled images; a separate sampler.
    DescriptorWrites& sampledImage(uint32_t binding, uint32_t element, VkImageView view,
                                   VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    DescriptorWrites& sampler(uint32_t binding, VkSampler sampler);
    void update(VkDevice device, VkDescriptorSet set);  // for pooled sets

private:
    // Only the frame graph pushes sets, from what a pass declared (core/frame_graph.h).
    friend class ::penumbra::FrameGraph;
    void push(const Context& ctx, VkCommandBuffer cmd, const Pipeline& pipeline, uint32_t set = 0);
    VkWriteDescriptorSet& add(uint32_t binding, VkDescriptorType type, uint32_t element = 0);
    std::vector<VkWriteDescriptorSet> writes_;
    std::deque<VkDescriptorImageInfo> images_;
    std::deque<VkDescriptorBufferInfo> buffers_;
};

// One descriptor set from a pool of its own, for a long-lived table that many passes bind as it is
// (written once with DescriptorWrites::update; the frame graph binds it beside the pushed set 0).
class DescriptorSet {
public:
    DescriptorSet() = default;
    DescriptorSet(Context& ctx, const std::vector<Binding>& bindings);
    ~DescriptorSet() { reset(); }
    DescriptorSet(DescriptorSet&& o) noexcept { *this = std::move(o); }
    DescriptorSet& operator=(DescriptorSet&& o) noexcept;
    VkDescriptorSet handle() const { return set_; }
    VkDescriptorSetLayout layout() const { return layout_.handle(); }
    void reset();

private:
    VkDevice device_ = VK_NULL_HANDLE;
    DescriptorLayout layout_;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
};

inline uint32_t divUp(uint32_t a, uint32_t b) { return (a + b - 1) / b; }

}  // namespace penumbra::vk
