#include "vk/pipeline.h"

#include <array>
#include <map>
#include <utility>

#include <fmt/format.h>

#include "vk/shader_registry.h"

namespace penumbra::vk {
namespace {

VkShaderModule createModule(VkDevice device, const std::string& key) {
    const EmbeddedShader& s = findShader(key);
    VkShaderModuleCreateInfo ci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    ci.codeSize = s.size;
    ci.pCode = reinterpret_cast<const uint32_t*>(s.code);
    VkShaderModule m;
    VK_CHECK(vkCreateShaderModule(device, &ci, nullptr, &m));
    return m;
}

VkPipelineShaderStageCreateInfo stage(VkShaderStageFlagBits s, VkShaderModule m) {
    VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage = s;
    info.module = m;
    info.pName = "main";
    return info;
}

std::string layoutsKey(const std::vector<VkDescriptorSetLayout>& sets, uint32_t pushBytes) {
    std::string key = fmt::format("push {}", pushBytes);
    for (VkDescriptorSetLayout s : sets) key += fmt::format(" set {}", fmt::ptr(s));
    return key;
}

std::string graphicsKey(const GraphicsDesc& d) {
    std::string key = fmt::format("G {} {} {} {} depth {} stride {} cull {} {} front {} bias {} clamp {} topo {}",
                                  d.vertexShader, d.fragmentShader, d.tessControlShader, d.tessEvalShader,
                                  int(d.depthFormat), d.vertexStride, d.cullMode, d.dynamicCullMode, int(d.frontFace),
                                  d.depthBias, d.depthClamp, int(d.topology));
    for (VkFormat f : d.colorFormats) key += fmt::format(" color {}", int(f));
    for (const VkVertexInputAttributeDescription& a : d.vertexAttributes)
        key += fmt::format(" attr {} {} {}", a.location, int(a.format), a.offset);
    return key;
}

}  // namespace

// Every pipeline and set layout lives as long as the device: rebuilding a technique finds its
// pipelines here (no second compilation, no pipeline growth over settings changes).
struct PipelineCache {
    VkDevice device;
    std::map<std::string, VkDescriptorSetLayout> layouts;
    std::map<std::string, std::pair<VkPipeline, VkPipelineLayout>> pipelines;
    std::map<VkDescriptorSetLayout, std::vector<Binding>> layoutBindings;
    std::vector<PipelineInterface> interfaces;
};

namespace {

void recordInterface(Context& ctx, std::vector<std::string> shaders, const std::vector<VkDescriptorSetLayout>& sets,
                     uint32_t pushBytes) {
    PipelineCache& cache = ctx.pipelineCache();
    PipelineInterface declared{std::move(shaders), {}, pushBytes};
    for (VkDescriptorSetLayout set : sets) {
        auto it = cache.layoutBindings.find(set);  // every layout made by DescriptorLayout is there
        declared.sets.push_back(it != cache.layoutBindings.end() ? it->second : std::vector<Binding>{});
    }
    cache.interfaces.push_back(std::move(declared));
}

}  // namespace

const std::vector<PipelineInterface>& declaredInterfaces(Context& ctx) { return ctx.pipelineCache().interfaces; }

void destroyPipelineCache(PipelineCache* cache) {
    if (!cache) return;
    for (auto& [key, p] : cache->pipelines) {
        vkDestroyPipeline(cache->device, p.first, nullptr);
        vkDestroyPipelineLayout(cache->device, p.second, nullptr);
    }
    for (auto& [key, l] : cache->layouts) vkDestroyDescriptorSetLayout(cache->device, l, nullptr);
    delete cache;
}

PipelineCache& Context::pipelineCache() {
    if (!pipelineCache_) pipelineCache_.reset(new PipelineCache{device_, {}, {}});
    return *pipelineCache_;
}

DescriptorLayout::DescriptorLayout(Context& ctx, const std::vector<Binding>& bindings, bool pushDescriptor)
    : device_(ctx.device()) {
    std::string key = pushDescriptor ? "push" : "pooled";
    for (const Binding& x : bindings) key += fmt::format(" {}:{}x{}", x.binding, int(x.type), x.count);
    PipelineCache& cache = ctx.pipelineCache();
    if (auto it = cache.layouts.find(key); it != cache.layouts.end()) {
        layout_ = it->second;
        return;
    }
    std::vector<VkDescriptorSetLayoutBinding> b;
    for (const Binding& x : bindings) b.push_back({x.binding, x.type, x.count, VK_SHADER_STAGE_ALL, nullptr});
    VkDescriptorSetLayoutCreateInfo ci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    ci.flags = pushDescriptor ? VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR : 0;
    ci.bindingCount = static_cast<uint32_t>(b.size());
    ci.pBindings = b.data();
    VK_CHECK(vkCreateDescriptorSetLayout(device_, &ci, nullptr, &layout_));
    cache.layouts[key] = layout_;
    cache.layoutBindings[layout_] = bindings;
}

DescriptorLayout& DescriptorLayout::operator=(DescriptorLayout&& o) noexcept {
    if (this != &o) {
        reset();
        device_ = o.device_;
        layout_ = std::exchange(o.layout_, VK_NULL_HANDLE);
    }
    return *this;
}

void DescriptorLayout::reset() { layout_ = VK_NULL_HANDLE; }  // the cache owns it

void Pipeline::createLayout(Context& ctx, const std::vector<VkDescriptorSetLayout>& sets, uint32_t pushBytes) {
    device_ = ctx.device();
    ctx_ = &ctx;
    VkPushConstantRange range{VK_SHADER_STAGE_ALL, 0, pushBytes};
    VkPipelineLayoutCreateInfo ci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    ci.setLayoutCount = static_cast<uint32_t>(sets.size());
    ci.pSetLayouts = sets.data();
    ci.pushConstantRangeCount = pushBytes ? 1 : 0;
    ci.pPushConstantRanges = &range;
    VK_CHECK(vkCreatePipelineLayout(device_, &ci, nullptr, &layout_));
}

bool Pipeline::fromCache(Context& ctx, const std::string& key) {
    ctx_ = &ctx;
    device_ = ctx.device();
    PipelineCache& cache = ctx.pipelineCache();
    auto it = cache.pipelines.find(key);
    if (it == cache.pipelines.end()) return false;
    pipeline_ = it->second.first;
    layout_ = it->second.second;
    return true;
}

void Pipeline::addToCache(Context& ctx, const std::string& key) {
    ctx.pipelineCache().pipelines[key] = {pipeline_, layout_};
    ctx.countPipeline(1);
}

Pipeline Pipeline::compute(Context& ctx, const std::string& shader, const std::vector<VkDescriptorSetLayout>& sets,
                           uint32_t pushBytes) {
    Pipeline p;
    p.bindPoint_ = VK_PIPELINE_BIND_POINT_COMPUTE;
    const std::string key = "C " + shader + " " + layoutsKey(sets, pushBytes);
    if (p.fromCache(ctx, key)) return p;
    p.createLayout(ctx, sets, pushBytes);
    recordInterface(ctx, {shader}, sets, pushBytes);
    VkShaderModule m = createModule(ctx.device(), shader);
    VkComputePipelineCreateInfo ci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    ci.stage = stage(VK_SHADER_STAGE_COMPUTE_BIT, m);
    ci.layout = p.layout_;
    VkResult r = vkCreateComputePipelines(ctx.device(), VK_NULL_HANDLE, 1, &ci, nullptr, &p.pipeline_);
    vkDestroyShaderModule(ctx.device(), m, nullptr);
    VK_CHECK(r);
    p.addToCache(ctx, key);
    return p;
}

Pipeline Pipeline::graphics(Context& ctx, const GraphicsDesc& d, const std::vector<VkDescriptorSetLayout>& sets,
                            uint32_t pushBytes) {
    Pipeline p;
    p.bindPoint_ = VK_PIPELINE_BIND_POINT_GRAPHICS;
    const std::string key = graphicsKey(d) + " " + layoutsKey(sets, pushBytes);
    if (p.fromCache(ctx, key)) return p;
    p.createLayout(ctx, sets, pushBytes);
    std::vector<std::string> shaders{d.vertexShader, d.fragmentShader, d.tessControlShader, d.tessEvalShader};
    std::erase(shaders, std::string());
    recordInterface(ctx, shaders, sets, pushBytes);
    std::vector<VkShaderModule> modules{createModule(ctx.device(), d.vertexShader)};
    std::vector<VkPipelineShaderStageCreateInfo> stages{stage(VK_SHADER_STAGE_VERTEX_BIT, modules[0])};
    if (!d.fragmentShader.empty()) {
        modules.push_back(createModule(ctx.device(), d.fragmentShader));
        stages.push_back(stage(VK_SHADER_STAGE_FRAGMENT_BIT, modules[1]));
    }
    const bool tessellated = !d.tessControlShader.empty();
    if (tessellated) {
        modules.push_back(createModule(ctx.device(), d.tessControlShader));
        stages.push_back(stage(VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, modules.back()));
        modules.push_back(createModule(ctx.device(), d.tessEvalShader));
        stages.push_back(stage(VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, modules.back()));
    }
    VkPipelineTessellationStateCreateInfo ts{VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_STATE_CREATE_INFO};
    ts.patchControlPoints = 3;
    VkVertexInputBindingDescription vb{0, d.vertexStride, VK_VERTEX_INPUT_RATE_VERTEX};
    VkPipelineVertexInputStateCreateInfo vi{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    if (d.vertexStride) {
        vi.vertexBindingDescriptionCount = 1;
        vi.pVertexBindingDescriptions = &vb;
        vi.vertexAttributeDescriptionCount = static_cast<uint32_t>(d.vertexAttributes.size());
        vi.pVertexAttributeDescriptions = d.vertexAttributes.data();
    }
    VkPipelineInputAssemblyStateCreateInfo ia{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    ia.topology = tessellated ? VK_PRIMITIVE_TOPOLOGY_PATCH_LIST : d.topology;
    VkPipelineViewportStateCreateInfo vp{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    vp.viewportCount = vp.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo rs{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    rs.polygonMode = VK_POLYGON_MODE_FILL;
    rs.cullMode = d.cullMode;
    rs.frontFace = d.frontFace;
    rs.depthBiasEnable = d.depthBias;
    rs.depthClampEnable = d.depthClamp;
    rs.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo ds{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    ds.depthTestEnable = ds.depthWriteEnable = d.depthFormat != VK_FORMAT_UNDEFINED;
    ds.depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    std::vector<VkPipelineColorBlendAttachmentState> blends(d.colorFormats.size());
    for (auto& b : blends) b.colorWriteMask = 0xF;
    VkPipelineColorBlendStateCreateInfo cb{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    cb.attachmentCount = static_cast<uint32_t>(blends.size());
    cb.pAttachments = blends.data();
    std::vector<VkDynamicState> dyn{VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    if (d.depthBias) dyn.push_back(VK_DYNAMIC_STATE_DEPTH_BIAS);
    if (d.dynamicCullMode) dyn.push_back(VK_DYNAMIC_STATE_CULL_MODE);
    VkPipelineDynamicStateCreateInfo dy{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dy.dynamicStateCount = static_cast<uint32_t>(dyn.size());
    dy.pDynamicStates = dyn.data();
    VkPipelineRenderingCreateInfo ri{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    ri.colorAttachmentCount = static_cast<uint32_t>(d.colorFormats.size());
    ri.pColorAttachmentFormats = d.colorFormats.data();
    ri.depthAttachmentFormat = d.depthFormat;
    VkGraphicsPipelineCreateInfo ci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO, &ri};
    ci.stageCount = static_cast<uint32_t>(stages.size());
    ci.pStages = stages.data();
    ci.pVertexInputState = &vi;
    ci.pInputAssemblyState = &ia;
    ci.pTessellationState = tessellated ? &ts : nullptr;
    ci.pViewportState = &vp;
    ci.pRasterizationState = &rs;
    ci.pMultisampleState = &ms;
    ci.pDepthStencilState = &ds;
    ci.pColorBlendState = &cb;
    ci.pDynamicState = &dy;
    ci.layout = p.layout_;
    VkResult r = vkCreateGraphicsPipelines(ctx.device(), VK_NULL_HANDLE, 1, &ci, nullptr, &p.pipeline_);
    for (VkShaderModule m : modules) vkDestroyShaderModule(ctx.device(), m, nullptr);
    VK_CHECK(r);
    p.addToCache(ctx, key);
    return p;
}

Pipeline& Pipeline::operator=(Pipeline&& o) noexcept {
    if (this != &o) {
        reset();
        ctx_ = o.ctx_;
        device_ = o.device_;
        pipeline_ = std::exchange(o.pipeline_, VK_NULL_HANDLE);
        layout_ = std::exchange(o.layout_, VK_NULL_HANDLE);
        bindPoint_ = o.bindPoint_;
    }
    return *this;
}

void Pipeline::reset() {
    // The device's PipelineCache owns both.
    pipeline_ = VK_NULL_HANDLE;
    layout_ = VK_NULL_HANDLE;
}

void Pipeline::pushConstants(VkCommandBuffer cmd, const void* data, uint32_t bytes) const {
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_ALL, 0, bytes, data);
}

ComputeKernel::ComputeKernel(Context& ctx, const std::string& shader, const std::vector<Binding>& bindings,
                             uint32_t pushBytes, const std::vector<VkDescriptorSetLayout>& moreSets) {
    layout = DescriptorLayout(ctx, bindings);
    std::vector<VkDescriptorSetLayout> sets{layout.handle()};
    sets.insert(sets.end(), moreSets.begin(), moreSets.end());
    pipeline = Pipeline::compute(ctx, shader, sets, pushBytes);
}

ComputeKernel::ComputeKernel(Context& ctx, const std::string& shader, const std::vector<VkDescriptorType>& types,
                             uint32_t pushBytes) {
    std::vector<Binding> bindings;
    for (uint32_t i = 0; i < types.size(); ++i) bindings.push_back({i, types[i]});
    *this = ComputeKernel(ctx, shader, bindings, pushBytes);
}

VkWriteDescriptorSet& DescriptorWrites::add(uint32_t binding, VkDescriptorType type, uint32_t element) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstBinding = binding;
    w.dstArrayElement = element;
    w.descriptorCount = 1;
    w.descriptorType = type;
    writes_.push_back(w);
    return writes_.back();
}

DescriptorWrites& DescriptorWrites::sampled(uint32_t binding, VkImageView view, VkSampler sampler,
                                            VkImageLayout layout) {
    images_.push_back({sampler, view, layout});
    add(binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER).pImageInfo = &images_.back();
    return *this;
}

DescriptorWrites& DescriptorWrites::storageImage(uint32_t binding, VkImageView view) {
    images_.push_back({VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL});
    add(binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE).pImageInfo = &images_.back();
    return *this;
}

DescriptorWrites& DescriptorWrites::storageBuffer(uint32_t binding, const Buffer& buffer) {
    buffers_.push_back({buffer.handle(), 0, VK_WHOLE_SIZE});
    add(binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER).pBufferInfo = &buffers_.back();
    return *this;
}

DescriptorWrites& DescriptorWrites::uniformBuffer(uint32_t binding, const Buffer& buffer) {
    buffers_.push_back({buffer.handle(), 0, VK_WHOLE_SIZE});
    add(binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER).pBufferInfo = &buffers_.back();
    return *this;
}

DescriptorWrites& DescriptorWrites::sampledImage(uint32_t binding, uint32_t element, VkImageView view,
                                                 VkImageLayout layout) {
    images_.push_back({VK_NULL_HANDLE, view, layout});
    add(binding, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, element).pImageInfo = &images_.back();
    return *this;
}

DescriptorWrites& DescriptorWrites::sampler(uint32_t binding, VkSampler sampler) {
    images_.push_back({sampler, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED});
    add(binding, VK_DESCRIPTOR_TYPE_SAMPLER).pImageInfo = &images_.back();
    return *this;
}

void DescriptorWrites::push(const Context& ctx, VkCommandBuffer cmd, const Pipeline& pipeline, uint32_t set) {
    ctx.cmdPushDescriptorSet(cmd, pipeline.bindPoint(), pipeline.layout(), set,
                             static_cast<uint32_t>(writes_.size()), writes_.data());
}

void DescriptorWrites::update(VkDevice device, VkDescriptorSet set) {
    for (auto& w : writes_) w.dstSet = set;
    vkUpdateDescriptorSets(device, static_cast<uint32_t>(writes_.size()), writes_.data(), 0, nullptr);
}

DescriptorSet::DescriptorSet(Context& ctx, const std::vector<Binding>& bindings)
    : device_(ctx.device()), layout_(ctx, bindings, false) {
    std::vector<VkDescriptorPoolSize> sizes;
    for (const Binding& b : bindings) sizes.push_back({b.type, b.count});
    VkDescriptorPoolCreateInfo pi{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pi.maxSets = 1;
    pi.poolSizeCount = static_cast<uint32_t>(sizes.size());
    pi.pPoolSizes = sizes.data();
    VK_CHECK(vkCreateDescriptorPool(device_, &pi, nullptr, &pool_));
    VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    ai.descriptorPool = pool_;
    ai.descriptorSetCount = 1;
    const VkDescriptorSetLayout layout = layout_.handle();
    ai.pSetLayouts = &layout;
    VK_CHECK(vkAllocateDescriptorSets(device_, &ai, &set_));
}

DescriptorSet& DescriptorSet::operator=(DescriptorSet&& o) noexcept {
    if (this != &o) {
        reset();
        device_ = o.device_;
        layout_ = std::move(o.layout_);
        pool_ = std::exchange(o.pool_, VK_NULL_HANDLE);
        set_ = std::exchange(o.set_, VK_NULL_HANDLE);
    }
    return *this;
}

void DescriptorSet::reset() {
    if (pool_) vkDestroyDescriptorPool(device_, pool_, nullptr);  // frees the set
    pool_ = VK_NULL_HANDLE;
    set_ = VK_NULL_HANDLE;
}

}  // namespace penumbra::vk
